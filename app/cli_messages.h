#pragma once
/// \file
/// How batch verbs talk: results on stdout, one-line errors and notes on stderr, and every
/// failure mapped to an exit code instead of an uncaught exception.

#include <QString>

#include <functional>

namespace trimlab::app {

void printLine(const QString& text);
/// "trimlab: error: <text>" on stderr (one line).
void printError(const QString& text);
/// "trimlab: note: <text>" on stderr.
void printNote(const QString& text);

/// Runs `body`; an exception becomes a one-line error and exit code 1.
int runGuarded(const std::function<int()>& body);

} // namespace trimlab::app
