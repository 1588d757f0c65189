#pragma once
// Contract: the one way hairpipe includes tinyobjloader (obj_import.cpp uses it, tinyobj_implementation.cpp
// compiles it): its namespace is renamed hp_tinyobj, so the copy compiled into hairpipe's library defines no
// tinyobj:: symbol that an application's own tinyobjloader would clash with.
#define tinyobj hp_tinyobj
#include <tiny_obj_loader.h>
