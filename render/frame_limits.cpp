#include "render/frame_limits.h"

#include "render/gl/gl_error.h"

#include <string>

namespace trimlab::render {

namespace {

std::string size(int width, int height)
{
    return std::to_string(width) + "x" + std::to_string(height);
}

} // namespace

void checkFrameLimits(FragmentMethodKind method, const GlCapabilities& capabilities, const MethodParameters& parameters,
                      std::optional<std::size_t> estimatedMethodBytes, int width, int height)
{
    const MethodInfo& info = methodInfo(method);
    const int maxSide = capabilities.maxTextureSize;
    if (maxSide > 0 && (width > maxSide || height > maxSide))
        throw GpuMemoryError("A " + size(width, height) + " frame is larger than this driver's " +
                             std::to_string(maxSide) +
                             " pixel limit for a texture side (GL_MAX_TEXTURE_SIZE). "
                             "Render a smaller image.");
    const int maxLayers = capabilities.maxArrayTextureLayers;
    if (info.usesK && maxLayers > 0 && parameters.k > maxLayers)
        throw GpuMemoryError(std::string(info.displayName) + " with k = " + std::to_string(parameters.k) +
                             " needs more texture layers than this driver's " + std::to_string(maxLayers) +
                             " (GL_MAX_ARRAY_TEXTURE_LAYERS). Lower k.");
    if (parameters.memoryBudgetBytes > 0 && estimatedMethodBytes &&
        *estimatedMethodBytes > parameters.memoryBudgetBytes)
        throw GpuMemoryError(std::string(info.displayName) +
                             (info.usesK ? " with k = " + std::to_string(parameters.k) : std::string()) + " needs " +
                             megabytesText(double(*estimatedMethodBytes)) + " at " + size(width, height) +
                             ", above the GPU memory budget of " + megabytesText(double(parameters.memoryBudgetBytes)) +
                             ". Raise the budget, lower " + (info.usesK ? "k or " : "") +
                             "the image size, or pick the S-buffer (memory in proportion to the fragments).");
}

} // namespace trimlab::render
