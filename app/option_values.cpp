#include "option_values.h"

#include <QCommandLineParser>

#include <cmath>

namespace trimlab::app {

std::optional<QString> parseIntegerFlag(const QCommandLineParser& parser, const QString& name, long long lo,
                                        long long hi, long long& out)
{
    if (!parser.isSet(name))
        return std::nullopt;
    bool ok = false;
    const long long value = parser.value(name).toLongLong(&ok);
    if (!ok || value < lo || value > hi)
        return QStringLiteral("--%1 must be an integer from %2 to %3, got '%4'")
            .arg(name)
            .arg(lo)
            .arg(hi)
            .arg(parser.value(name));
    out = value;
    return std::nullopt;
}

std::optional<QString> parseRealFlag(const QCommandLineParser& parser, const QString& name, double lo, double hi,
                                     double& out)
{
    if (!parser.isSet(name))
        return std::nullopt;
    bool ok = false;
    const double value = parser.value(name).toDouble(&ok);
    if (!ok || !std::isfinite(value) || value < lo || value > hi)
        return QStringLiteral("--%1 must be a number from %2 to %3, got '%4'")
            .arg(name)
            .arg(lo)
            .arg(hi)
            .arg(parser.value(name));
    out = value;
    return std::nullopt;
}

} // namespace trimlab::app
