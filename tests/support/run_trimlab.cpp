#include "run_trimlab.h"

#include <QProcess>

namespace trimlab::test {

QString trimlabExecutable()
{
    return qEnvironmentVariable("TRIMLAB_TEST_EXECUTABLE", QStringLiteral(TRIMLAB_EXECUTABLE));
}

Run runTrimlab(const QStringList& arguments, int timeoutMs)
{
    QProcess process;
    process.start(trimlabExecutable(), arguments);
    if (!process.waitForFinished(timeoutMs))
        return {};
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
            QString::fromLocal8Bit(process.readAllStandardOutput()),
            QString::fromLocal8Bit(process.readAllStandardError())};
}

} // namespace trimlab::test
