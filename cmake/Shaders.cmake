# onelight_add_shaders(TARGET SOURCES...): compiles GLSL into SPIR-V at build time with
# glslangValidator; each shader becomes a header <name>_<stage>.spv.h holding a uint32_t array
# named <name>_<stage>_spv. A shader error fails the build. Includes resolve against shaders/.
function(onelight_add_shaders target)
  set(outdir ${CMAKE_CURRENT_BINARY_DIR}/spirv)
  file(MAKE_DIRECTORY ${outdir})
  set(headers)
  foreach(src ${ARGN})
    get_filename_component(abs ${src} ABSOLUTE)
    get_filename_component(name ${src} NAME)
    string(REPLACE "." "_" var ${name})
    set(out ${outdir}/${name}.spv.h)
    add_custom_command(
      OUTPUT ${out}
      COMMAND Vulkan::glslangValidator -V --target-env vulkan1.1 -I${PROJECT_SOURCE_DIR}/shaders
              --vn ${var}_spv -o ${out} ${abs}
      DEPENDS ${abs} ${ONELIGHT_SHARED_GLSL}
      COMMENT "glslang ${name}"
      VERBATIM)
    list(APPEND headers ${out})
  endforeach()
  add_custom_target(${target}_spirv DEPENDS ${headers})
  add_library(${target} INTERFACE)
  add_dependencies(${target} ${target}_spirv)
  target_include_directories(${target} INTERFACE ${outdir})
endfunction()
