#include "mfr/trim_frame.h"

#include "gl/shader_library.h"

namespace trimlab::render {

GLuint trimProgram(TrimFrame& frame, const QString& name, QStringList defines)
{
    defines.append(frame.modeDefines);
    return frame.shaders.program(name, defines);
}

} // namespace trimlab::render
