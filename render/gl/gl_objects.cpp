#include "gl/gl_objects.h"

#include "gl/gl_error.h"

#include <string>

namespace trimlab::render {

void checkAllocation(GlFunctions& gl, const char* what, double bytes)
{
    bool outOfMemory = false;
    for (GLenum e = gl.glGetError(); e != GL_NO_ERROR; e = gl.glGetError())
        outOfMemory = outOfMemory || e == GL_OUT_OF_MEMORY;
    if (outOfMemory)
        throw GpuMemoryError("The GPU ran out of memory allocating the " + std::string(what) + " (" +
                             std::to_string(static_cast<long long>(bytes / (1024.0 * 1024.0) + 0.5)) +
                             " MB). Lower k or the viewport size, or close other GPU applications.");
}

} // namespace trimlab::render
