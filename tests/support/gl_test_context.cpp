#include "gl_test_context.h"

#include "render/gl/gl_error.h"

#include <cstdlib>

namespace trimlab::test {

std::unique_ptr<render::OffscreenGlContext> tryCreateGlContext(QString* why)
{
    try {
        return std::make_unique<render::OffscreenGlContext>();
    } catch (const render::GlError& e) {
        if (why)
            *why = QString::fromStdString(e.what());
        return nullptr;
    }
}

bool glRequired()
{
    const char* value = std::getenv("TRIMLAB_REQUIRE_GL");
    return value && std::string(value) == "1";
}

} // namespace trimlab::test
