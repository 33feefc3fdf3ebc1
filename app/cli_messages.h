#pragma once
/// \file
/// How batch verbs talk: results on stdout, one-line errors and notes on stderr, and every
/// failure mapped to an exit code instead of an uncaught exception.

#include <QString>

class QCommandLineParser;

#include <functional>

namespace trimlab::app {

void printLine(const QString& text);
/// "trimlab: error: <text>" on stderr (one line).
void printError(const QString& text);
/// "trimlab: note: <text>" on stderr.
void printNote(const QString& text);

/// The parser's help text with its usage line naming the verb ("Usage: trimlab render
/// [options] source") instead of whatever argv[0] was.
[[nodiscard]] QString verbHelpText(const QCommandLineParser& parser, const QString& verb);

/// Runs `body`; an exception becomes a one-line error and exit code 1.
int runGuarded(const std::function<int()>& body);

} // namespace trimlab::app
