// stb's implementations, compiled once here: vcpkg and Homebrew ship stb as headers only (Debian's
// libstb.so has them compiled, but the workbook links the same way everywhere).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
