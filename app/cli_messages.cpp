#include "app/cli_messages.h"

#include <QCommandLineParser>
#include <QRegularExpression>

#include <cstdio>
#include <exception>

namespace trimlab::app {

namespace {

// Multi-line messages (a shader build log) would break "one line per error" for scripts
// that read stderr; the first line says what failed, the rest follows indented.
QString indentContinuationLines(const QString& text)
{
    QString result = text.trimmed();
    result.replace(QLatin1Char('\n'), QStringLiteral("\n    "));
    return result;
}

} // namespace

void printLine(const QString& text)
{
    std::fprintf(stdout, "%s\n", text.toLocal8Bit().constData());
    std::fflush(stdout);
}

void printError(const QString& text)
{
    std::fprintf(stderr, "trimlab: error: %s\n", indentContinuationLines(text).toLocal8Bit().constData());
}

void printNote(const QString& text)
{
    std::fprintf(stderr, "trimlab: note: %s\n", indentContinuationLines(text).toLocal8Bit().constData());
}

QString verbHelpText(const QCommandLineParser& parser, const QString& verb)
{
    QString text = parser.helpText();
    static const QRegularExpression usage(QStringLiteral("^Usage: \\S+"));
    text.replace(usage, QStringLiteral("Usage: trimlab ") + verb);
    return text;
}

int runGuarded(const std::function<int()>& body)
{
    try {
        return body();
    } catch (const std::exception& e) {
        printError(QString::fromUtf8(e.what()));
        return 1;
    }
}

} // namespace trimlab::app
