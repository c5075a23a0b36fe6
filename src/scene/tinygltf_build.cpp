// tinygltf's implementation, compiled from Debian's header into this library. Debian also ships
// it as a shared library (libtinygltf), but libdraco, which assimp loads, exports tinygltf's
// symbols from a copy of its own built with other options, and the dynamic linker binds to
// whichever is loaded first: compiled here, the reader's calls always reach this copy.
// Images are decoded by scene/texture_file.cpp, so tinygltf's own stb_image use is left out
// (TINYGLTF_NO_STB_IMAGE and _WRITE, defined for the whole library in CMakeLists.txt).

#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
