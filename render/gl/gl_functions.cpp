#include "render/gl/gl_functions.h"

#include "render/gl/gl_error.h"

#include <QOpenGLContext>
#include <QOpenGLVersionFunctionsFactory>

namespace trimlab::render {

GlFunctions& currentGlFunctions()
{
    QOpenGLContext* context = QOpenGLContext::currentContext();
    if (!context)
        throw GlUnavailableError("No OpenGL context is current (programming error in the caller).");
    auto* functions = QOpenGLVersionFunctionsFactory::get<GlFunctions>(context);
    if (!functions)
        throw GlUnavailableError("The OpenGL context does not provide the OpenGL 4.3 core functions TrimLab needs.");
    return *functions;
}

} // namespace trimlab::render
