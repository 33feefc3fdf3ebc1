#include "ui/render_panel/render_settings_store.h"

#include "core/trim/inspect_parameters.h"
#include "render/mfr/fragment_method.h"
#include "render/mfr/method_parameter_table.h"
#include "ui/common/parameter_settings.h"

#include <QSettings>

#include <limits>

namespace trimlab::ui {

namespace {

const QString kTrimEnabled = QStringLiteral("render/trimEnabled");
const QString kRule = QStringLiteral("render/rule");
const QString kClipEnabled = QStringLiteral("render/clipEnabled");
const QString kClipNormalX = QStringLiteral("render/clipNormalX");
const QString kClipNormalY = QStringLiteral("render/clipNormalY");
const QString kClipNormalZ = QStringLiteral("render/clipNormalZ");
const QString kClipOffset = QStringLiteral("render/clipOffset");
const QString kMethod = QStringLiteral("render/method");
const QString kClassification = QStringLiteral("render/classification");
const QString kCapEnabled = QStringLiteral("render/capEnabled");
const QString kCapPattern = QStringLiteral("render/capPattern");
const QString kHighlightCollisions = QStringLiteral("render/highlightCollisions");
const QString kHighlightCoplanar = QStringLiteral("render/highlightCoplanar");
const QString kXrayMode = QStringLiteral("render/xrayMode");

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
    constexpr double kLargest = std::numeric_limits<double>::max();
    return readBoundedNumber(settings, key, -kLargest, kLargest, fallback);
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

/// X-ray: "off", "opaque" or "translucent" and its values, each falling back on its own.
void loadTransparency(const QSettings& settings, const TransparencySettings& fallback, TransparencySettings& xray)
{
    const QString mode = settings.value(kXrayMode).toString();
    const std::optional<TrimDisplay> display = parseTrimDisplay(mode.toStdString());
    xray.enabled = mode == QStringLiteral("off") ? false : (display ? true : fallback.enabled);
    xray.display = display.value_or(fallback.display);
    xray.layerAlpha = readParameter(settings, inspect_parameters::kLayerAlpha);
    xray.ghostAlpha = readParameter(settings, inspect_parameters::kGhostAlpha);
    xray.density = readParameter(settings, inspect_parameters::kDensity);
    xray.fresnelExponent = readParameter(settings, inspect_parameters::kFresnel);
}

void saveTransparency(QSettings& settings, const TransparencySettings& xray)
{
    const std::string_view display = trimDisplayName(xray.display);
    settings.setValue(kXrayMode, xray.enabled ? QString::fromLatin1(display.data(), qsizetype(display.size()))
                                              : QStringLiteral("off"));
    writeParameter(settings, inspect_parameters::kLayerAlpha, xray.layerAlpha);
    writeParameter(settings, inspect_parameters::kGhostAlpha, xray.ghostAlpha);
    writeParameter(settings, inspect_parameters::kDensity, xray.density);
    writeParameter(settings, inspect_parameters::kFresnel, xray.fresnelExponent);
}

/// Capping and highlighting, each field falling back on its own.
void loadInspection(const QSettings& settings, const RenderChoices& fallback, RenderChoices& choices)
{
    choices.trim.cap.enabled = settings.value(kCapEnabled, fallback.trim.cap.enabled).toBool();
    choices.trim.cap.pattern =
        parseCapPattern(settings.value(kCapPattern).toString().toStdString()).value_or(fallback.trim.cap.pattern);
    choices.capSpacingFraction = readParameter(settings, inspect_parameters::kCapSpacing);
    choices.trim.highlight.collisions =
        settings.value(kHighlightCollisions, fallback.trim.highlight.collisions).toBool();
    choices.trim.highlight.coplanar = settings.value(kHighlightCoplanar, fallback.trim.highlight.coplanar).toBool();
    loadTransparency(settings, fallback.trim.transparency, choices.trim.transparency);
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
    choices.k = readParameterAs<int>(settings, render::method_parameters::kK);
    choices.method = loadMethod(settings, fallback.method);
    choices.sharedCounters = readParameterAs<int>(settings, render::method_parameters::kSharedCounters);
    choices.memoryBudgetMegabytes = readParameterAs<int>(settings, render::method_parameters::kMemoryBudget);
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
    writeParameter(settings, inspect_parameters::kCapSpacing, choices.capSpacingFraction);
    settings.setValue(kHighlightCollisions, choices.trim.highlight.collisions);
    settings.setValue(kHighlightCoplanar, choices.trim.highlight.coplanar);
    saveTransparency(settings, choices.trim.transparency);
    writeParameter(settings, render::method_parameters::kK, choices.k);
    const std::string_view method = render::methodInfo(choices.method).id;
    settings.setValue(kMethod, QString::fromLatin1(method.data(), qsizetype(method.size())));
    writeParameter(settings, render::method_parameters::kSharedCounters, choices.sharedCounters);
    writeParameter(settings, render::method_parameters::kMemoryBudget, choices.memoryBudgetMegabytes);
    settings.setValue(kClassification, choices.dynamicRules ? QStringLiteral("dynamic") : QStringLiteral("static"));
}

} // namespace trimlab::ui
