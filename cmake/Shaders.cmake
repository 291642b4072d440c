# onelight_add_shaders(TARGET SOURCES...): compiles GLSL into SPIR-V at build time with
# glslangValidator; each shader becomes a header <name>.<stage>.spv.h holding a uint32_t array
# named k<Name><Stage>Spirv (forward.frag: kForwardFragSpirv). A shader error fails the build.
# Includes resolve against shaders/ and the shader's own folder.
function(onelight_add_shaders target)
  set(outdir ${CMAKE_CURRENT_BINARY_DIR}/spirv)
  file(MAKE_DIRECTORY ${outdir})
  set(headers)
  foreach(src ${ARGN})
    get_filename_component(abs ${src} ABSOLUTE)
    get_filename_component(name ${src} NAME)
    # forward.frag -> kForwardFragSpirv: a constant, named as every constant is (docs/style.md).
    string(REGEX REPLACE "[._]" ";" parts ${name})
    set(var "k")
    foreach(part ${parts})
      string(SUBSTRING ${part} 0 1 first)
      string(TOUPPER ${first} first)
      string(SUBSTRING ${part} 1 -1 rest)
      string(APPEND var "${first}${rest}")
    endforeach()
    set(out ${outdir}/${name}.spv.h)
    # glslang's depfile lists every file the shader includes, however deep, so a change to any
    # of them recompiles it.
    add_custom_command(
      OUTPUT ${out}
      COMMAND Vulkan::glslangValidator -V --target-env vulkan1.1 -I${PROJECT_SOURCE_DIR}/shaders
              --vn ${var}Spirv --depfile ${out}.d -o ${out} ${abs}
      DEPENDS ${abs}
      DEPFILE ${out}.d
      COMMENT "glslang ${name}"
      VERBATIM)
    list(APPEND headers ${out})
  endforeach()
  add_custom_target(${target}_spirv DEPENDS ${headers})
  add_library(${target} INTERFACE)
  add_dependencies(${target} ${target}_spirv)
  target_include_directories(${target} INTERFACE ${outdir})
endfunction()
