#include "render_settings_store.h"

#include "mfr/fragment_method.h"

#include <QDir>
#include <QSettings>

#include <cmath>

namespace trimlab::ui {

namespace {

const QString kTrimEnabled = QStringLiteral("render/trimEnabled");
const QString kRule = QStringLiteral("render/rule");
const QString kClipEnabled = QStringLiteral("render/clipEnabled");
const QString kClipNormalX = QStringLiteral("render/clipNormalX");
const QString kClipNormalY = QStringLiteral("render/clipNormalY");
const QString kClipNormalZ = QStringLiteral("render/clipNormalZ");
const QString kClipOffset = QStringLiteral("render/clipOffset");
const QString kK = QStringLiteral("render/k");
const QString kMethod = QStringLiteral("render/method");
const QString kSharedCounters = QStringLiteral("render/sharedCounters");
const QString kMemoryBudget = QStringLiteral("render/memoryBudgetMB");
const QString kClassification = QStringLiteral("render/classification");
const QString kLastDirectory = QStringLiteral("paths/lastDirectory");

/// The stored number at `key`, or `fallback` when missing, unparsable or not finite.
double finiteValue(const QSettings& settings, const QString& key, double fallback)
{
    bool ok = false;
    const double value = settings.value(key).toDouble(&ok);
    return ok && std::isfinite(value) ? value : fallback;
}

ClipPlane loadClipPlane(const QSettings& settings, const ClipPlane& fallback)
{
    ClipPlane plane = fallback;
    plane.enabled = settings.value(kClipEnabled, fallback.enabled).toBool();
    const glm::dvec3 normal{finiteValue(settings, kClipNormalX, fallback.normal.x),
                            finiteValue(settings, kClipNormalY, fallback.normal.y),
                            finiteValue(settings, kClipNormalZ, fallback.normal.z)};
    if (normal != glm::dvec3(0.0))
        plane.normal = normal;
    plane.offset = finiteValue(settings, kClipOffset, fallback.offset);
    return plane;
}

/// The stored integer at `key` when it lies in [lo, hi], else `fallback`.
int boundedInt(const QSettings& settings, const QString& key, int lo, int hi, int fallback)
{
    bool ok = false;
    const int value = settings.value(key).toInt(&ok);
    return ok && value >= lo && value <= hi ? value : fallback;
}

/// The stored method id when this build has that method, else `fallback`.
render::FragmentMethodKind loadMethod(const QSettings& settings, render::FragmentMethodKind fallback)
{
    return render::parseFragmentMethod(settings.value(kMethod).toString().toStdString()).value_or(fallback);
}

} // namespace

RenderChoices loadRenderChoices(const QSettings& settings)
{
    const RenderChoices fallback = firstStartRenderChoices();
    RenderChoices choices = fallback;
    choices.trim.trimEnabled = settings.value(kTrimEnabled, fallback.trim.trimEnabled).toBool();
    const std::string ruleText = settings.value(kRule).toString().toStdString();
    choices.trim.rule = parseStaticRule(ruleText).value_or(fallback.trim.rule);
    choices.trim.clip = loadClipPlane(settings, fallback.trim.clip);
    choices.k = boundedInt(settings, kK, 1, render::MethodParameters::kMaxK, fallback.k);
    choices.method = loadMethod(settings, fallback.method);
    choices.sharedCounters = boundedInt(settings, kSharedCounters, 1, kMaxSharedCounters, fallback.sharedCounters);
    choices.memoryBudgetMegabytes =
        boundedInt(settings, kMemoryBudget, 0, kMaxMemoryBudgetMegabytes, fallback.memoryBudgetMegabytes);
    choices.dynamicRules = settings.value(kClassification).toString() == QStringLiteral("dynamic");
    return choices;
}

void saveRenderChoices(QSettings& settings, const RenderChoices& choices)
{
    settings.setValue(kTrimEnabled, choices.trim.trimEnabled);
    settings.setValue(kRule, QString::fromLatin1(ruleName(choices.trim.rule).data(),
                                                 qsizetype(ruleName(choices.trim.rule).size())));
    settings.setValue(kClipEnabled, choices.trim.clip.enabled);
    settings.setValue(kClipNormalX, choices.trim.clip.normal.x);
    settings.setValue(kClipNormalY, choices.trim.clip.normal.y);
    settings.setValue(kClipNormalZ, choices.trim.clip.normal.z);
    settings.setValue(kClipOffset, choices.trim.clip.offset);
    settings.setValue(kK, choices.k);
    const std::string_view method = render::methodInfo(choices.method).id;
    settings.setValue(kMethod, QString::fromLatin1(method.data(), qsizetype(method.size())));
    settings.setValue(kSharedCounters, choices.sharedCounters);
    settings.setValue(kMemoryBudget, choices.memoryBudgetMegabytes);
    settings.setValue(kClassification, choices.dynamicRules ? QStringLiteral("dynamic") : QStringLiteral("static"));
}

QString loadLastDirectory(const QSettings& settings)
{
    const QString directory = settings.value(kLastDirectory).toString();
    return !directory.isEmpty() && QDir(directory).exists() ? directory : QDir::homePath();
}

void saveLastDirectory(QSettings& settings, const QString& directory)
{
    settings.setValue(kLastDirectory, directory);
}

} // namespace trimlab::ui
