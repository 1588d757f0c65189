#pragma once
// Contract: what the draw passes render into: colour and depth formats and the sample count. Given
// by the embedding application (its own attachments) or by RenderTargets (hairpipe's offscreen ones).
// Defined once, in the public API (hairpipe/settings.h).
#include "hairpipe/settings.h"

namespace hp::render {
using AttachmentFormats = hairpipe::AttachmentFormats;
}  // namespace hp::render
