#pragma once
// hairpipe: a strand-hair pipeline on Vulkan 1.3 (simulation, tessellation, interpolation, opacity
// shadow maps, fibre shading), recorded into the application's own command buffers and attachments.
// This header includes the whole public API:
//   hairpipe/context.h   the device hairpipe works on (adopted from the application, or headless)
//   hairpipe/asset.h     heads of hair as data: loadAsset, defaultHeadAsset
//   hairpipe/renderer.h  Renderer (per device) and Instance (per head); the synchronisation contract
//   hairpipe/settings.h  the values the application sets (lights, views, motion, material, look, ...)
//   hairpipe/math.h      Vec3 and Mat4 as plain structs
//   hairpipe/result.h    Status and Result<T>: every call is noexcept and returns its failure
//   hairpipe/version.h   the version
// Everything is in namespace hairpipe. docs/API.md is the guide; the README's "Embedding" a short one.
#include "hairpipe/asset.h"
#include "hairpipe/context.h"
#include "hairpipe/math.h"
#include "hairpipe/renderer.h"
#include "hairpipe/result.h"
#include "hairpipe/settings.h"
#include "hairpipe/version.h"
