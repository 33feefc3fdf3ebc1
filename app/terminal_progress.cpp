#include "app/terminal_progress.h"

#include <QElapsedTimer>

#include <cstdio>
#include <unistd.h>

namespace trimlab::app {

TaskControl terminalProgress()
{
    TaskControl control;
    if (!isatty(fileno(stderr)))
        return control;
    control.progress = [](const TaskProgress& p) {
        std::fprintf(stderr, "\r%.*s %zu/%zu\x1b[K", int(p.stage.size()), p.stage.data(), p.done, p.total);
        if (p.done == p.total)
            std::fputc('\n', stderr);
    };
    return control;
}

double lapMilliseconds(QElapsedTimer& timer)
{
    const double ms = double(timer.nsecsElapsed()) * 1e-6;
    timer.restart();
    return ms;
}

} // namespace trimlab::app
