#include "app/gui_launcher.h"

#include "app/cli_messages.h"
#include "app/display_available.h"

#include "render/gl/offscreen_gl_context.h"
#include "render/gl/wide_vector_state.h"
#include "ui/window/main_window.h"

#include <QAbstractEventDispatcher>
#include <QApplication>
#include <QSurfaceFormat>

namespace trimlab::app {

int runGui(int argc, char** argv)
{
    if (!displayAvailable()) {
        printError("the GUI needs a display; for a headless image use: xvfb-run -a trimlab render demo:pushed-sphere "
                   "-o out.png");
        return 1;
    }
    // Before QApplication: every OpenGL widget then gets a 4.3 core context.
    QSurfaceFormat::setDefaultFormat(render::OffscreenGlContext::requestedFormat());
    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("TrimLab"));
    QApplication::setApplicationName(QStringLiteral("TrimLab"));
    QApplication::setApplicationVersion(QStringLiteral(TRIMLAB_VERSION));
    QApplication::setDesktopFileName(QStringLiteral("trimlab")); // resources/trimlab.desktop
    // Whatever the platform plugin and the OpenGL driver left in the wide vector registers is
    // ended before each round of events, so the brush's and the panels' CPU work does not pay
    // for it (render/gl/wide_vector_state.h: 9x on NVIDIA's driver).
    QObject::connect(QAbstractEventDispatcher::instance(), &QAbstractEventDispatcher::awake,
                     [] { render::leaveWideVectorState(); });
    render::leaveWideVectorState();
    ui::MainWindow window;
    window.show();
    if (argc > 1)
        window.openSource(QString::fromLocal8Bit(argv[1]));
    return application.exec();
}

} // namespace trimlab::app
