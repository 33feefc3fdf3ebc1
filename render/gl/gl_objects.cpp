#include "render/gl/gl_objects.h"

#include "render/gl/context_reset.h"
#include "render/gl/gl_error.h"

#include <cstdio>
#include <string>

namespace trimlab::render {

std::string megabytesText(double bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MB", bytes / (1024.0 * 1024.0));
    return text;
}

void checkAllocation(GlFunctions& gl, const char* what, double bytes)
{
    bool outOfMemory = false;
    bool contextLost = false;
    for (GLenum e = gl.glGetError(); e != GL_NO_ERROR; e = gl.glGetError()) {
        outOfMemory = outOfMemory || e == GL_OUT_OF_MEMORY;
        contextLost = contextLost || e == kGlContextLost;
    }
    if (contextLost) // a reset, not a full GPU: the allocation may well fit again
        throw GlContextLostError(ContextReset::Unknown);
    if (outOfMemory)
        throw GpuMemoryError("The GPU ran out of memory allocating the " + std::string(what) + " (" +
                             std::to_string(static_cast<long long>(bytes / (1024.0 * 1024.0) + 0.5)) +
                             " MB). Lower k or the viewport size, or close other GPU applications.");
}

} // namespace trimlab::render
