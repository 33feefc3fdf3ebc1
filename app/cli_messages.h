#pragma once
/// \file
/// How batch verbs talk: results on stdout, one-line errors and notes on stderr, and every
/// failure mapped to an exit code instead of an uncaught exception.

#include "core/trim/hole_closing.h"

#include <QString>

class QCommandLineParser;

#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace trimlab::app {

void printLine(const QString& text);
/// "trimlab: error: <text>" on stderr (one line).
void printError(const QString& text);
/// "trimlab: note: <text>" on stderr.
void printNote(const QString& text);
/// --close-holes: the note of what was closed in `name` ("closed 2 holes of 19 edges in
/// horse-gallop"), a fan that crosses the surface included (holeClosingText).
void noteHolesClosed(const std::string& name, const HoleClosing& closing);

/// The parser's help text with its usage line naming the verb ("Usage: trimlab render
/// [options] source") instead of whatever argv[0] was.
[[nodiscard]] QString verbHelpText(const QCommandLineParser& parser, const QString& verb);

/// For a verb's parsed arguments: prints the help (exit code 0) or the one-line error
/// (exit code 2) when the arguments gave no options; nullopt when they did.
template <class Options>
[[nodiscard]] std::optional<int> exitIfNotParsed(const std::variant<Options, QString>& parsed, const QString& help)
{
    const QString* error = std::get_if<QString>(&parsed);
    if (!error)
        return std::nullopt;
    if (!help.isEmpty()) {
        printLine(help);
        return 0;
    }
    printError(*error);
    return 2;
}

/// Runs `body`; an exception becomes a one-line error and exit code 1, naming `inputs`
/// when its message names none of them (so a batch farm's log says which file failed).
/// An allocation the system refused (std::bad_alloc, from this thread or a worker's, which
/// parallelFor hands back after every worker has stopped) becomes "out of memory working
/// on <inputs>" with what to change.
int runGuarded(const std::function<int()>& body, const std::vector<std::string>& inputs = {});

} // namespace trimlab::app
