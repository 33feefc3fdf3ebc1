#pragma once
/// \file
/// The main() of a widget test that needs a display: where the environment names none,
/// the offscreen platform is chosen so that QApplication starts instead of aborting on
/// xcb, and initTestCase can skip (or fail under TRIMLAB_REQUIRE_GL=1) with the reason.
/// 96 dpi fixes the widget sizes, so that frames compare at the sizes the tests expect.

#include <QApplication>
#include <QtGlobal>
#include <QtTest>

/// Defines main() running the QtTest object `TestClass` (use instead of QTEST_MAIN).
#define TRIMLAB_WIDGET_TEST_MAIN(TestClass)                                                                            \
    int main(int argc, char** argv)                                                                                    \
    {                                                                                                                  \
        if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") &&                \
            qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))                                                            \
            qputenv("QT_QPA_PLATFORM", "offscreen");                                                                   \
        QApplication app(argc, argv);                                                                                  \
        app.setAttribute(Qt::AA_Use96Dpi, true);                                                                       \
        TestClass test;                                                                                                \
        QTEST_SET_MAIN_SOURCE_PATH                                                                                     \
        return QTest::qExec(&test, argc, argv);                                                                        \
    }
