#include "ui/render_panel/render_settings_store.h"

#include "render/mfr/fragment_method.h"

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
const QString kCapEnabled = QStringLiteral("render/capEnabled");
const QString kCapPattern = QStringLiteral("render/capPattern");
const QString kCapSpacingFraction = QStringLiteral("render/capSpacingFraction");
const QString kHighlightCollisions = QStringLiteral("render/highlightCollisions");
const QString kHighlightCoplanar = QStringLiteral("render/highlightCoplanar");
const QString kXrayMode = QStringLiteral("render/xrayMode");
const QString kXrayLayerAlpha = QStringLiteral("render/xrayLayerAlpha");
const QString kXrayGhostAlpha = QStringLiteral("render/xrayGhostAlpha");
const QString kXrayDensity = QStringLiteral("render/xrayDensity");
const QString kXrayFresnel = QStringLiteral("render/xrayFresnel");

/// The keys of clipping plane `index` > 0 (plane 0 keeps the keys of the one plane of
/// earlier versions): "render/clipPlaneN/enabled", ".../normalX" etc.
struct ClipKeys {
    QString enabled, normalX, normalY, normalZ, offset;
};

ClipKeys clipKeys(int index)
{
    if (index == 0)
        return {kClipEnabled, kClipNormalX, kClipNormalY, kClipNormalZ, kClipOffset};
    const QString group = QStringLiteral("render/clipPlane%1/").arg(index);
    return {group + QStringLiteral("enabled"), group + QStringLiteral("normalX"), group + QStringLiteral("normalY"),
            group + QStringLiteral("normalZ"), group + QStringLiteral("offset")};
}

/// The stored number at `key`, or `fallback` when missing, unparsable or not finite.
double finiteValue(const QSettings& settings, const QString& key, double fallback)
{
    bool ok = false;
    const double value = settings.value(key).toDouble(&ok);
    return ok && std::isfinite(value) ? value : fallback;
}

ClipPlane loadClipPlane(const QSettings& settings, const ClipKeys& keys, const ClipPlane& fallback)
{
    ClipPlane plane = fallback;
    plane.enabled = settings.value(keys.enabled, fallback.enabled).toBool();
    const glm::dvec3 normal{finiteValue(settings, keys.normalX, fallback.normal.x),
                            finiteValue(settings, keys.normalY, fallback.normal.y),
                            finiteValue(settings, keys.normalZ, fallback.normal.z)};
    if (normal != glm::dvec3(0.0))
        plane.normal = normal;
    plane.offset = finiteValue(settings, keys.offset, fallback.offset);
    return plane;
}

void saveClipPlane(QSettings& settings, const ClipKeys& keys, const ClipPlane& plane)
{
    settings.setValue(keys.enabled, plane.enabled);
    settings.setValue(keys.normalX, plane.normal.x);
    settings.setValue(keys.normalY, plane.normal.y);
    settings.setValue(keys.normalZ, plane.normal.z);
    settings.setValue(keys.offset, plane.offset);
}

/// The stored number at `key` when finite and in [lo, hi], else `fallback`.
double boundedValue(const QSettings& settings, const QString& key, double lo, double hi, double fallback)
{
    const double value = finiteValue(settings, key, fallback);
    return value >= lo && value <= hi ? value : fallback;
}

/// X-ray: "off", "opaque" or "translucent" and its values, each falling back on its own.
void loadTransparency(const QSettings& settings, const TransparencySettings& fallback, TransparencySettings& xray)
{
    const QString mode = settings.value(kXrayMode).toString();
    const std::optional<TrimDisplay> display = parseTrimDisplay(mode.toStdString());
    xray.enabled = mode == QStringLiteral("off") ? false : (display ? true : fallback.enabled);
    xray.display = display.value_or(fallback.display);
    xray.layerAlpha = boundedValue(settings, kXrayLayerAlpha, 0.0, 1.0, fallback.layerAlpha);
    xray.ghostAlpha = boundedValue(settings, kXrayGhostAlpha, 0.0, 1.0, fallback.ghostAlpha);
    xray.density = boundedValue(settings, kXrayDensity, 0.0, 100.0, fallback.density);
    xray.fresnelExponent = boundedValue(settings, kXrayFresnel, 0.0, 16.0, fallback.fresnelExponent);
}

void saveTransparency(QSettings& settings, const TransparencySettings& xray)
{
    const std::string_view display = trimDisplayName(xray.display);
    settings.setValue(kXrayMode, xray.enabled ? QString::fromLatin1(display.data(), qsizetype(display.size()))
                                              : QStringLiteral("off"));
    settings.setValue(kXrayLayerAlpha, xray.layerAlpha);
    settings.setValue(kXrayGhostAlpha, xray.ghostAlpha);
    settings.setValue(kXrayDensity, xray.density);
    settings.setValue(kXrayFresnel, xray.fresnelExponent);
}

/// Capping and highlighting, each field falling back on its own.
void loadInspection(const QSettings& settings, const RenderChoices& fallback, RenderChoices& choices)
{
    choices.trim.cap.enabled = settings.value(kCapEnabled, fallback.trim.cap.enabled).toBool();
    choices.trim.cap.pattern = parseCapPattern(settings.value(kCapPattern).toString().toStdString())
                                   .value_or(fallback.trim.cap.pattern);
    const double fraction = finiteValue(settings, kCapSpacingFraction, fallback.capSpacingFraction);
    const bool inRange = fraction >= RenderChoices::kMinCapSpacingFraction &&
                         fraction <= RenderChoices::kMaxCapSpacingFraction;
    choices.capSpacingFraction = inRange ? fraction : fallback.capSpacingFraction;
    choices.trim.highlight.collisions =
        settings.value(kHighlightCollisions, fallback.trim.highlight.collisions).toBool();
    choices.trim.highlight.coplanar = settings.value(kHighlightCoplanar, fallback.trim.highlight.coplanar).toBool();
    loadTransparency(settings, fallback.trim.transparency, choices.trim.transparency);
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
    for (int i = 0; i < kMaxClipPlanes; ++i)
        choices.trim.clipPlane(i) = loadClipPlane(settings, clipKeys(i), fallback.trim.clipPlane(i));
    loadInspection(settings, fallback, choices);
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
    settings.setValue(kRule, QString::fromStdString(ruleName(choices.trim.rule)));
    for (int i = 0; i < kMaxClipPlanes; ++i)
        saveClipPlane(settings, clipKeys(i), choices.trim.clipPlane(i));
    settings.setValue(kCapEnabled, choices.trim.cap.enabled);
    const std::string_view pattern = capPatternName(choices.trim.cap.pattern);
    settings.setValue(kCapPattern, QString::fromLatin1(pattern.data(), qsizetype(pattern.size())));
    settings.setValue(kCapSpacingFraction, choices.capSpacingFraction);
    settings.setValue(kHighlightCollisions, choices.trim.highlight.collisions);
    settings.setValue(kHighlightCoplanar, choices.trim.highlight.coplanar);
    saveTransparency(settings, choices.trim.transparency);
    settings.setValue(kK, choices.k);
    const std::string_view method = render::methodInfo(choices.method).id;
    settings.setValue(kMethod, QString::fromLatin1(method.data(), qsizetype(method.size())));
    settings.setValue(kSharedCounters, choices.sharedCounters);
    settings.setValue(kMemoryBudget, choices.memoryBudgetMegabytes);
    settings.setValue(kClassification, choices.dynamicRules ? QStringLiteral("dynamic") : QStringLiteral("static"));
}

} // namespace trimlab::ui
