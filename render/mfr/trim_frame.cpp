#include "render/mfr/trim_frame.h"

#include "render/gl/shader_library.h"

namespace trimlab::render {

GLuint trimProgram(TrimFrame& frame, const QString& name, QStringList defines)
{
    // TRANSPARENCY changes only what a resolve pass writes; building the capture passes
    // with it would compile identical programs again under another name.
    const bool resolve = name.endsWith(QLatin1String("_resolve"));
    for (const QString& define : frame.modeDefines)
        if (resolve || define != QLatin1String("TRANSPARENCY"))
            defines.append(define);
    return frame.shaders.program(name, defines);
}

} // namespace trimlab::render
