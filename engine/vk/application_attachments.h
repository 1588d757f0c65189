#pragma once
// Contract: the application's attachments (hairpipe::AttachmentFormats) that hairpipe's graphics pipelines
// draw into inside the application's rendering: checked by field (validateAttachmentFormats: no device
// needed), checked against a device (requireAttachmentSupport: the formats' features and the sample count),
// and written into a pipeline's description (setApplicationAttachments), so every such pipeline matches the
// rendering the same way (colour, depth and, where the application attaches one, stencil).
#include "hairpipe_volk.h"

#include "engine/vk/pipeline.h"
#include "hairpipe/settings.h"

namespace hp::vk {
class Context;

inline constexpr std::size_t kMaxOtherColors = 7;  // AttachmentFormats::otherColors
// Throws hp::Error naming the field: a colour of UNDEFINED or a depth format, a depth that is not one,
// a stencil that is not UNDEFINED nor the depth's own combined format, a sample count that is not one of
// 1, 2, 4, 8 or 16, more than kMaxOtherColors other colours or one that is a depth format (VK_FORMAT_UNDEFINED
// is an unused slot of the rendering).
void validateAttachmentFormats(const hairpipe::AttachmentFormats& formats);
// Throws hp::Error naming the format and the device where the colour cannot be a blended colour attachment,
// another colour a colour attachment, the depth a depth attachment (and, with sampledDepth, the compute
// raster's sampled image; unused slots are not checked), the sample count is not supported for both, the colours are more than the device
// attaches, or other colours need independentBlend where the context has it off.
void requireAttachmentSupport(const Context& ctx, const hairpipe::AttachmentFormats& formats, bool sampledDepth);
// The description's colours (hairpipe's one written, then the application's others unwritten), depth,
// stencil, sample count and the depth test's direction.
void setApplicationAttachments(GraphicsPipelineDesc& desc, const hairpipe::AttachmentFormats& formats);
}  // namespace hp::vk
