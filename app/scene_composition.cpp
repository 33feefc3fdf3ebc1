#include "app/scene_composition.h"

#include "app/cli_messages.h"

#include "core/catalog/closed_scene.h"
#include "core/scene/world_geometry.h"
#include "core/trim/clip_set.h"
#include "core/trim/csg_expression.h"
#include "core/trim/csg_object_ids.h"
#include "core/trim/static_rule.h"

#include <QCommandLineParser>

#include <cmath>
#include <string>
#include <vector>

namespace trimlab::app {

namespace {

QString transformSyntaxError(const QString& text, const QString& why)
{
    return QStringLiteral("--object-transform must look like 1=TX,TY,TZ[,RX,RY,RZ[,S]] (%1), got '%2'").arg(why, text);
}

} // namespace

QString objectTransformHelp()
{
    return QStringLiteral(
        "Place object ID (ids count across the sources in order): ID=TX,TY,TZ moves it; ID=TX,TY,TZ,RX,RY,RZ also "
        "rotates it by RX, RY, RZ degrees about x, then y, then z; a seventh number scales it uniformly (> 0). "
        "Replaces the placement the file gave it, as the Scene panel does. Repeatable.");
}

std::optional<QString> parseObjectTransform(const QString& text, std::vector<ObjectTransformOption>& out)
{
    const qsizetype equals = text.indexOf(QLatin1Char('='));
    bool ok = false;
    const int id = equals > 0 ? text.left(equals).toInt(&ok) : -1;
    if (!ok || id < 0 || id >= int(Scene::maxObjects))
        return transformSyntaxError(text, QStringLiteral("an object id from 0 to %1").arg(Scene::maxObjects - 1));
    const QStringList parts = text.mid(equals + 1).split(QLatin1Char(','));
    if (parts.size() != 3 && parts.size() != 6 && parts.size() != 7)
        return transformSyntaxError(text, QStringLiteral("3, 6 or 7 numbers"));
    double values[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0};
    for (qsizetype i = 0; i < parts.size(); ++i) {
        values[i] = parts[i].trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(values[i]))
            return transformSyntaxError(text, QStringLiteral("'%1' is not a finite number").arg(parts[i]));
    }
    if (values[6] < ObjectTransform::kMinScale)
        return transformSyntaxError(text, QStringLiteral("the scale must be positive"));
    ObjectTransformOption option;
    option.object = id;
    option.transform.translation = {values[0], values[1], values[2]};
    option.transform.rotationDegrees = {values[3], values[4], values[5]};
    option.transform.scale = values[6];
    out.push_back(option);
    return std::nullopt;
}

std::optional<QString> applyObjectTransforms(const std::vector<ObjectTransformOption>& transforms, Scene& scene)
{
    for (const ObjectTransformOption& option : transforms) {
        if (option.object >= int(scene.objects.size()))
            return QStringLiteral("--object-transform names object %1, but the scene has %2 object(s) (ids 0 to %3)")
                .arg(option.object)
                .arg(scene.objects.size())
                .arg(int(scene.objects.size()) - 1);
        SceneObject& object = scene.objects[std::size_t(option.object)];
        object.modelMatrix = option.transform.modelMatrix();
        if (const std::string problem = placementProblem(object); !problem.empty())
            return QStringLiteral("--object-transform %1: object %2 (%3): %4")
                .arg(QString::number(option.object), QString::number(option.object),
                     QString::fromStdString(object.name), QString::fromStdString(problem));
    }
    return std::nullopt;
}

std::optional<QString> takeSources(const QStringList& positional, const QString& verb,
                                   std::vector<std::string>& sources)
{
    if (positional.isEmpty())
        return QStringLiteral("%1 needs at least one source (a mesh file or demo:NAME; several make one scene); see "
                              "trimlab %1 --help")
            .arg(verb);
    if (positional.size() > qsizetype(Scene::maxObjects))
        return QStringLiteral("%1 takes at most %2 sources, got %3")
            .arg(verb)
            .arg(Scene::maxObjects)
            .arg(positional.size());
    for (const QString& source : positional)
        sources.push_back(source.toStdString());
    return std::nullopt;
}

std::optional<QString> parseRuleOption(const QString& text, TrimSettings& trim)
{
    if (text == QLatin1String("none")) {
        trim.trimEnabled = false;
        return std::nullopt;
    }
    const std::optional<StaticRule> rule = parseStaticRule(text.toStdString());
    if (!rule)
        return QStringLiteral("unknown --rule '%1' (use %2, or none)")
            .arg(text, QString::fromStdString(staticRuleNamesHelp()));
    trim.rule = *rule;
    return std::nullopt;
}

std::optional<QString> parseObjectRuleOption(const QString& text, CsgSettings& csg)
{
    const qsizetype equals = text.indexOf(QLatin1Char('='));
    bool ok = false;
    const int id = equals > 0 ? text.left(equals).toInt(&ok) : -1;
    if (!ok || id < 0 || id >= kMaxCsgOperands)
        return QStringLiteral("--object-rule must look like 0=parity with an object id from 0 to %1, got '%2'")
            .arg(kMaxCsgOperands - 1)
            .arg(text);
    const std::optional<StaticRule> rule = parseStaticRule(text.mid(equals + 1).toStdString());
    if (!rule)
        return QStringLiteral("--object-rule %1: unknown rule '%2' (use %3)")
            .arg(text, text.mid(equals + 1), QString::fromStdString(staticRuleNamesHelp()));
    csg.objectRules[std::size_t(id)] = *rule;
    return std::nullopt;
}

std::optional<QString> parseCsgOption(const QString& text, CsgSettings& csg)
{
    std::string error;
    const std::optional<CsgExpression> expression = parseCsgExpression(text.toStdString(), &error);
    if (!expression)
        return QStringLiteral("--csg '%1': %2").arg(text, QString::fromStdString(error));
    csg.expression = *expression;
    return std::nullopt;
}

void adoptSavedCsg(const LoadedScene& loaded, CsgSettings& csg, bool expressionGiven, bool trimEnabled)
{
    for (std::size_t id = 0; id < csg.objectRules.size(); ++id)
        if (!csg.objectRules[id])
            csg.objectRules[id] = loaded.savedCsg.objectRules[id];
    if (!expressionGiven && trimEnabled)
        csg.expression = loaded.savedCsg.expression;
}

std::optional<QString> checkObjectIds(const CsgSettings& csg, std::size_t objectCount)
{
    const std::optional<CsgObjectIdProblem> problem = csgObjectIdOutsideScene(csg, objectCount);
    if (!problem)
        return std::nullopt;
    return QStringLiteral("%1 %2").arg(problem->inExpression ? QStringLiteral("--csg")
                                                             : QStringLiteral("--object-rule"),
                                       QString::fromStdString(csgObjectIdReason(problem->id, objectCount)));
}

std::optional<QString> parseClipOptions(const QCommandLineParser& parser, TrimSettings& trim)
{
    if (!parser.isSet("clip"))
        return std::nullopt;
    std::vector<std::string> texts;
    for (const QString& text : parser.values("clip"))
        texts.push_back(text.toStdString());
    std::string error;
    const std::optional<ClipSet> clips = parseClipSet(texts, &error);
    if (!clips)
        return QStringLiteral("--clip: ") + QString::fromStdString(error);
    trim.setClipSet(*clips);
    return std::nullopt;
}

void closeHolesNoted(LoadedScene& loaded)
{
    noteHolesClosed(loaded.displayName, closeSceneHoles(loaded));
}

} // namespace trimlab::app
