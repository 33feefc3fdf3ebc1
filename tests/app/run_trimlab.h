#pragma once
/// \file
/// Running the trimlab executable in the app tests (each test target defines
/// TRIMLAB_EXECUTABLE as the binary this build made).

#include <QProcess>
#include <QString>
#include <QStringList>

namespace trimlab::test {

/// What one run printed and how it ended; exitCode −1 when it crashed or timed out.
struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

/// Runs trimlab with `arguments`, waiting up to `timeoutMs`. TRIMLAB_TEST_EXECUTABLE,
/// when set, names another trimlab binary to test (an installed one, say).
inline Run runTrimlab(const QStringList& arguments, int timeoutMs = 120000)
{
    QProcess process;
    process.start(qEnvironmentVariable("TRIMLAB_TEST_EXECUTABLE", QStringLiteral(TRIMLAB_EXECUTABLE)), arguments);
    if (!process.waitForFinished(timeoutMs))
        return {};
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
            QString::fromLocal8Bit(process.readAllStandardOutput()),
            QString::fromLocal8Bit(process.readAllStandardError())};
}

} // namespace trimlab::test
