#include "app/option_values.h"

#include <QCommandLineParser>

#include <cmath>

namespace trimlab::app {

namespace {

/// The shared rule of every numeric flag: not given → nullopt and `out` unchanged; given →
/// `parse(text)` must return a value in [lo, hi], else the one-line error
/// "--NAME must be KIND from LO to HI, got 'TEXT'". `kind` is the noun phrase of the
/// message ("an integer", "a number"); `lo` and `hi` are printed with QString::arg for T, so
/// the integer and real messages keep their own number formats.
template <typename T, typename Parse>
std::optional<QString> parseRangedFlag(const QCommandLineParser& parser, const QString& name, const char* kind, T lo,
                                       T hi, T& out, Parse parse)
{
    if (!parser.isSet(name))
        return std::nullopt;
    const QString text = parser.value(name);
    const std::optional<T> value = parse(text);
    if (!value || *value < lo || *value > hi)
        return QStringLiteral("--%1 must be %2 from %3 to %4, got '%5'")
            .arg(name, QLatin1String(kind))
            .arg(lo)
            .arg(hi)
            .arg(text);
    out = *value;
    return std::nullopt;
}

} // namespace

std::optional<QString> parseIntegerFlag(const QCommandLineParser& parser, const QString& name, long long lo,
                                        long long hi, long long& out)
{
    const auto parse = [](const QString& text) -> std::optional<long long> {
        bool ok = false;
        const long long value = text.toLongLong(&ok);
        return ok ? std::optional<long long>(value) : std::nullopt;
    };
    return parseRangedFlag(parser, name, "an integer", lo, hi, out, parse);
}

std::optional<QString> parseRealFlag(const QCommandLineParser& parser, const QString& name, double lo, double hi,
                                     double& out)
{
    // NaN and infinities parse as doubles but are never a valid option value.
    const auto parse = [](const QString& text) -> std::optional<double> {
        bool ok = false;
        const double value = text.toDouble(&ok);
        return ok && std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
    };
    return parseRangedFlag(parser, name, "a number", lo, hi, out, parse);
}

} // namespace trimlab::app
