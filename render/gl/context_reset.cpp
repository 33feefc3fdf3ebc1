#include "render/gl/context_reset.h"

#include <QOpenGLFunctions>

namespace trimlab::render {
namespace {

// The enums of GL 4.5 / KHR_robustness (GL/gl.h of some platforms lacks them).
constexpr unsigned kGuiltyContextReset = 0x8253;
constexpr unsigned kInnocentContextReset = 0x8254;
constexpr unsigned kResetNotificationStrategy = 0x8256;
constexpr unsigned kLoseContextOnReset = 0x8252;

} // namespace

ContextReset contextResetFromStatus(unsigned status)
{
    switch (status) {
    case 0:
        return ContextReset::None;
    case kGuiltyContextReset:
        return ContextReset::Guilty;
    case kInnocentContextReset:
        return ContextReset::Innocent;
    default:
        return ContextReset::Unknown;
    }
}

std::string contextResetMessage(ContextReset reset)
{
    switch (reset) {
    case ContextReset::None:
        return "The OpenGL context is intact.";
    case ContextReset::Guilty:
        return "The graphics driver reset the GPU because TrimLab's frame took too long or faulted; every GPU "
               "buffer was lost. Pick a method that holds less (S-buffer), lower k or the view size.";
    case ContextReset::Innocent:
        return "The graphics driver reset the GPU because of another application; every GPU buffer was lost.";
    case ContextReset::Unknown:
        break;
    }
    return "The graphics driver reset the GPU (cause unknown); every GPU buffer was lost. If this repeats, pick a "
           "method that holds less (S-buffer), lower k or the view size, or update the graphics driver.";
}

ContextResetWatch::ContextResetWatch(QOpenGLContext& context) : m_context(&context)
{
    GLint strategy = 0;
    context.functions()->glGetIntegerv(kResetNotificationStrategy, &strategy);
    context.functions()->glGetError(); // drivers without robustness refuse the query
    if (unsigned(strategy) != kLoseContextOnReset)
        return;
    // The core name (4.5), else the extensions' (a 4.3 context may offer only these).
    for (const char* name :
         {"glGetGraphicsResetStatus", "glGetGraphicsResetStatusKHR", "glGetGraphicsResetStatusARB"}) {
        if (const QFunctionPointer function = context.getProcAddress(name)) {
            m_status = reinterpret_cast<StatusFunction>(function);
            return;
        }
    }
}

ContextReset ContextResetWatch::poll() const
{
    if (!m_context->isValid())
        return ContextReset::Unknown;
    return m_status ? contextResetFromStatus(m_status()) : ContextReset::None;
}

void ContextResetWatch::throwIfReset() const
{
    if (const ContextReset reset = poll(); reset != ContextReset::None)
        throw GlContextLostError(reset);
}

} // namespace trimlab::render
