#include "app/parameter_options.h"

#include <QCommandLineParser>
#include <QStringList>

namespace trimlab::app {

namespace {

QString text(std::string_view view)
{
    return QString::fromUtf8(view.data(), qsizetype(view.size()));
}

QString valueName(const ParameterSpec& spec)
{
    switch (spec.kind) {
    case ParameterKind::Integer:
        return QStringLiteral("N");
    case ParameterKind::Real:
        return QStringLiteral("X");
    case ParameterKind::Boolean:
        return QStringLiteral("on|off");
    case ParameterKind::Choice:
        break;
    }
    QStringList names;
    for (const ChoiceValue& choice : spec.choices)
        if (choice.commandLine)
            names << text(choice.name);
    return names.join(QLatin1Char('|'));
}

// The one-line refusal of `given` for --flag.
QString refusal(const ParameterSpec& spec, const QString& given)
{
    const QString flag = text(spec.flag);
    const QString range = QString::fromStdString(parameterRangeText(spec));
    switch (spec.kind) {
    case ParameterKind::Integer:
        return QStringLiteral("--%1 must be an integer from %2, got '%3'").arg(flag, range, given);
    case ParameterKind::Real:
        return QStringLiteral("--%1 must be a number from %2, got '%3'").arg(flag, range, given);
    case ParameterKind::Boolean:
        return QStringLiteral("--%1 must be on or off, got '%2'").arg(flag, given);
    case ParameterKind::Choice:
        break;
    }
    return QStringLiteral("unknown --%1 '%2' (use %3)").arg(flag, given, range);
}

} // namespace

QCommandLineOption commandLineOption(const ParameterSpec& spec)
{
    const QString help = QString::fromStdString(parameterHelpText(spec));
    if (spec.switchFlag)
        return QCommandLineOption(text(spec.flag), help);
    return QCommandLineOption(text(spec.flag), help, valueName(spec));
}

void addParameterOptions(QCommandLineParser& parser, std::span<const ParameterSpec* const> table)
{
    for (const ParameterSpec* spec : table)
        if (!spec->flag.empty())
            parser.addOption(commandLineOption(*spec));
}

std::optional<QString> parseParameter(const QCommandLineParser& parser, const ParameterSpec& spec, double& value)
{
    const QString flag = text(spec.flag);
    if (spec.flag.empty() || !parser.isSet(flag))
        return std::nullopt;
    if (spec.switchFlag) {
        value = 1.0;
        return std::nullopt;
    }
    const QString given = parser.value(flag);
    const std::optional<double> parsed = parseParameterValue(spec, given.toStdString());
    const ChoiceValue* choice =
        parsed && spec.kind == ParameterKind::Choice ? choiceWithValue(spec, int(*parsed)) : nullptr;
    if (!parsed || !acceptsValue(spec, *parsed) || (choice && !choice->commandLine))
        return refusal(spec, given);
    value = *parsed;
    return std::nullopt;
}

} // namespace trimlab::app
