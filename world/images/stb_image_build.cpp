// stb_image's implementation, built alone so that the flags it needs apply to it and to nothing
// else (world/CMakeLists.txt): the decoders of the formats levels use, with readable failures.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_HDR
#define STBI_ONLY_TGA  // Quake 3 textures
#define STBI_FAILURE_USERMSG
// Zeroed allocations: stb leaves parts of a damaged JPEG's planes unwritten (a frame component no
// scan covers, a scan cut short where a restart marker is missing) and then reads them, so with
// malloc the same bytes decoded to different texels from run to run (found by fuzz_image). Zeroed,
// they decode to the same wrong texels every time. (stb grows its PNG buffers with realloc, and
// writes every byte of those before it reads it.)
#include <cstdlib>
#define STBI_MALLOC(size) std::calloc(1, size)
#define STBI_REALLOC(pointer, size) std::realloc(pointer, size)
#define STBI_FREE(pointer) std::free(pointer)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image.h>
#pragma GCC diagnostic pop
