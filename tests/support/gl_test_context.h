#pragma once
/// \file
/// An offscreen OpenGL 4.3 context for render tests. Without one a test may skip — unless
/// TRIMLAB_REQUIRE_GL=1, which turns the skip into a failure (CI sets it).

#include "render/gl/offscreen_gl_context.h"

#include <QStandardPaths>
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
#define TRIMLAB_INIT_GL_CONTEXT(variable)                                                                              \
    do {                                                                                                               \
        QString why_;                                                                                                  \
        variable = trimlab::test::tryCreateGlContext(&why_);                                                           \
        if (!variable) {                                                                                               \
            if (trimlab::test::glRequired())                                                                           \
                QFAIL(qPrintable("TRIMLAB_REQUIRE_GL=1 but no OpenGL 4.3 context: " + why_));                          \
            QSKIP(qPrintable("No OpenGL 4.3 context: " + why_));                                                       \
        }                                                                                                              \
    } while (false)

/// In a test function whose work needs OpenGL elsewhere (a trimlab child process that
/// renders): checks that a 4.3 context can be made here, then releases it; without one
/// the function skips — or fails under TRIMLAB_REQUIRE_GL=1 — with the reason.
#define TRIMLAB_SKIP_WITHOUT_GL()                                                                                      \
    do {                                                                                                               \
        QString why_;                                                                                                  \
        if (!trimlab::test::tryCreateGlContext(&why_)) {                                                               \
            if (trimlab::test::glRequired())                                                                           \
                QFAIL(qPrintable("TRIMLAB_REQUIRE_GL=1 but no OpenGL 4.3 context: " + why_));                          \
            QSKIP(qPrintable("no OpenGL 4.3 context: " + why_));                                                       \
        }                                                                                                              \
    } while (false)

/// In initTestCase() of a widget test: standard paths in test mode (settings, recovery
/// files and caches never touch the user's) and the OpenGL 4.3 check of
/// TRIMLAB_INIT_GL_CONTEXT (skip, or fail under TRIMLAB_REQUIRE_GL=1), which the viewport
/// needs.
#define TRIMLAB_INIT_WIDGET_TEST()                                                                                     \
    do {                                                                                                               \
        QStandardPaths::setTestModeEnabled(true);                                                                      \
        std::unique_ptr<trimlab::render::OffscreenGlContext> probe_;                                                   \
        TRIMLAB_INIT_GL_CONTEXT(probe_);                                                                               \
    } while (false)
