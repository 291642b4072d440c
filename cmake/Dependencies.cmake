# Every third-party dependency of onelight, found once (see docs/toolchain.md, "CMake").
# Imported targets are used everywhere; their headers are system headers, so the project's
# -Werror applies to its own code only.
find_package(Threads REQUIRED)  # before glslang: its config needs Threads::Threads
find_package(Vulkan REQUIRED COMPONENTS glslangValidator)
find_package(glfw3 3.3 REQUIRED)
find_package(glslang 12 CONFIG REQUIRED)
find_package(OpenMesh REQUIRED)
find_package(embree 3 REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(glm REQUIRED)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
# pk3 archives (Quake 3 maps). Through pkg-config: Debian 12's libzip CMake config names the
# zipcmp/zipmerge/ziptool programs, which libzip-dev does not install, and fails without them.
find_package(PkgConfig REQUIRED)
pkg_check_modules(LIBZIP REQUIRED IMPORTED_TARGET libzip)
find_path(STB_INCLUDE_DIR stb_image.h PATH_SUFFIXES stb REQUIRED)
find_path(TINYEXR_INCLUDE_DIR tinyexr.h REQUIRED)
find_library(TINYEXR_LIBRARY tinyexr REQUIRED)

add_library(onelight_stb INTERFACE)
target_include_directories(onelight_stb SYSTEM INTERFACE ${STB_INCLUDE_DIR})

add_library(onelight_tinyexr INTERFACE)
target_include_directories(onelight_tinyexr SYSTEM INTERFACE ${TINYEXR_INCLUDE_DIR})
target_link_libraries(onelight_tinyexr INTERFACE ${TINYEXR_LIBRARY})
