#pragma once
/// \file
/// An offscreen OpenGL 4.3 context for render tests. Without one a test may skip — unless
/// TRIMLAB_REQUIRE_GL=1, which turns the skip into a failure (CI sets it).

#include "gl/offscreen_gl_context.h"

#include <QString>

#include <memory>

namespace trimlab::test {

/// The context, or nullptr with the reason in `why`.
[[nodiscard]] std::unique_ptr<render::OffscreenGlContext> tryCreateGlContext(QString* why);
/// True when TRIMLAB_REQUIRE_GL is set to 1.
[[nodiscard]] bool glRequired();

} // namespace trimlab::test

/// In initTestCase(): creates `variable` (a unique_ptr<OffscreenGlContext>) or skips /
/// fails the whole test case with the reason.
#define TRIMLAB_INIT_GL_CONTEXT(variable)                                                                  \
    do {                                                                                                   \
        QString why_;                                                                                      \
        variable = trimlab::test::tryCreateGlContext(&why_);                                               \
        if (!variable) {                                                                                   \
            if (trimlab::test::glRequired())                                                               \
                QFAIL(qPrintable("TRIMLAB_REQUIRE_GL=1 but no OpenGL 4.3 context: " + why_));              \
            QSKIP(qPrintable("No OpenGL 4.3 context: " + why_));                                           \
        }                                                                                                  \
    } while (false)
