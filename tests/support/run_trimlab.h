#pragma once
/// \file
/// Running the trimlab executable of this build as a child process, the way users and
/// scripts call it, for the app tests (library trimlab_cli_test_support, which also makes
/// the build produce the executable before any test that links it).

#include <QString>
#include <QStringList>

namespace trimlab::test {

/// What one run printed and how it ended; exitCode −1 when it crashed, could not start or
/// timed out.
struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

/// Runs trimlab with `arguments`, waiting up to `timeoutMs`; a run past the limit is
/// killed and reported with exitCode −1. TRIMLAB_TEST_EXECUTABLE, when set, names another
/// trimlab binary to test (an installed one, say).
[[nodiscard]] Run runTrimlab(const QStringList& arguments, int timeoutMs = 120000);

/// The trimlab binary runTrimlab starts (TRIMLAB_TEST_EXECUTABLE or this build's), for
/// tests that drive the process themselves (killing it, say).
[[nodiscard]] QString trimlabExecutable();

} // namespace trimlab::test

/// In a test function: `run` (a trimlab::test::Run) ended with `code` and printed exactly
/// one line on stderr, "trimlab: error: …" containing `message` — the documented contract
/// of bad arguments (2) and bad files (1). `run` is evaluated once, so a runTrimlab(...)
/// call may stand there.
#define TRIMLAB_VERIFY_ONE_LINE_ERROR(run, code, message)                                                              \
    do {                                                                                                               \
        const trimlab::test::Run& run_ = (run);                                                                        \
        QCOMPARE(run_.exitCode, (code));                                                                               \
        QVERIFY2(run_.err.startsWith(QLatin1String("trimlab: error: ")) && run_.err.contains(message),                 \
                 qPrintable(run_.err));                                                                                \
        QCOMPARE(run_.err.trimmed().count(QLatin1Char('\n')), 0);                                                      \
    } while (false)
