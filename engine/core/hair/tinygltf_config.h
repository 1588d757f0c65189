#pragma once
// Contract: the one way hairpipe includes tinygltf: every translation unit sees the same configuration (no
// image decoding, no file system of its own: the files a glTF names are read through callbacks that
// gltf_mesh.cpp hands it), as the inline parts of its header depend on it; and its namespace is renamed
// hp_tinygltf, so the copy compiled into hairpipe's library defines no tinygltf:: symbol that an
// application's own tinygltf (another version, another configuration) would clash with.
#define tinygltf hp_tinygltf
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
#include <fstream>  // its writer needs it even without a file system

#include <tiny_gltf.h>
