#include "app/cli_messages.h"

#include "core/util/printable_text.h"

#include <QCommandLineParser>
#include <QRegularExpression>

#include <cstdio>
#include <exception>
#include <new>

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

// What reaches the terminal: no control or escape sequence from a file (printable_text.h).
QByteArray terminalBytes(const QString& text)
{
    const QByteArray utf8 = text.toUtf8();
    const std::string printable = printableText(std::string_view(utf8.constData(), std::size_t(utf8.size())));
    return QString::fromUtf8(printable.data(), qsizetype(printable.size())).toLocal8Bit();
}

} // namespace

void printLine(const QString& text)
{
    std::fprintf(stdout, "%s\n", terminalBytes(text).constData());
    std::fflush(stdout);
}

void printError(const QString& text)
{
    std::fprintf(stderr, "trimlab: error: %s\n", terminalBytes(indentContinuationLines(text)).constData());
}

void printNote(const QString& text)
{
    std::fprintf(stderr, "trimlab: note: %s\n", terminalBytes(indentContinuationLines(text)).constData());
}

void noteHolesClosed(const std::string& name, const HoleClosing& closing)
{
    printNote(QStringLiteral("closed %1 in %2")
                  .arg(QString::fromStdString(holeClosingText(closing)), QString::fromStdString(name)));
}

QString verbHelpText(const QCommandLineParser& parser, const QString& verb)
{
    QString text = parser.helpText();
    static const QRegularExpression usage(QStringLiteral("^Usage: \\S+"));
    text.replace(usage, QStringLiteral("Usage: trimlab ") + verb);
    return text;
}

namespace {

std::string joined(const std::vector<std::string>& inputs)
{
    std::string files;
    for (const std::string& input : inputs)
        files += (files.empty() ? "" : ", ") + input;
    return files;
}

// A message that names none of the inputs (a system error from deep inside: a thread that
// could not start) gets them appended, so that a batch farm's log says which file failed.
std::string withInputs(std::string message, const std::vector<std::string>& inputs)
{
    for (const std::string& input : inputs)
        if (message.find(input) != std::string::npos)
            return message;
    return inputs.empty() ? message : message + " (working on " + joined(inputs) + ")";
}

} // namespace

int runGuarded(const std::function<int()>& body, const std::vector<std::string>& inputs)
{
    try {
        return body();
    } catch (const std::bad_alloc&) {
        printError(QStringLiteral("out of memory working on %1: the system refused an allocation (set "
                                  "TRIMLAB_MEMORY_BUDGET below this process's memory limit to have such work "
                                  "refused before it starts, or give it more memory)")
                       .arg(inputs.empty() ? QStringLiteral("the request") : QString::fromStdString(joined(inputs))));
        return 1;
    } catch (const std::exception& e) {
        // Escaped before decoding, so that bytes that are not UTF-8 show as such.
        printError(QString::fromStdString(printableText(withInputs(e.what(), inputs))));
        return 1;
    }
}

} // namespace trimlab::app
