#pragma once
/// \file
/// Numeric options of the batch verbs (segment, skin, skeleton): an option that was given
/// must parse and lie in its range, or the verb stops with one line saying which option,
/// the range and what was given.

#include <QString>

#include <optional>

class QCommandLineParser;

namespace trimlab::app {

/// When --`name` was given: its integer value in [lo, hi] into `out`, else the error text
/// ("--nodes must be an integer from 2 to 10000, got 'x'"). Not given: nullopt, `out`
/// unchanged.
[[nodiscard]] std::optional<QString> parseIntegerFlag(const QCommandLineParser& parser, const QString& name,
                                                      long long lo, long long hi, long long& out);
/// The same for a finite real number in [lo, hi].
[[nodiscard]] std::optional<QString> parseRealFlag(const QCommandLineParser& parser, const QString& name, double lo,
                                                   double hi, double& out);

} // namespace trimlab::app
