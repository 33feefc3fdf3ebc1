#include "core/timeline/view_settings.h"

#include <glm/geometric.hpp>

#include <stdexcept>

namespace trimlab::timeline {

namespace {

/// The centre of `bounds` and its extent along the unit `normal` (see RelativeClipPlane).
struct Support {
    glm::dvec3 centre{0.0};
    double extent = 1.0;
};

Support supportAlong(const glm::dvec3& normal, const Bounds& bounds)
{
    if (!bounds.valid())
        return {glm::dvec3(0.0), glm::dot(glm::abs(normal), glm::dvec3(1.0))};
    const glm::dvec3 half = 0.5 * (bounds.max - bounds.min);
    const double extent = glm::dot(glm::abs(normal), half);
    const double radius = bounds.radius();
    if (extent > 1e-9 * radius)
        return {bounds.center(), extent};
    return {bounds.center(), radius > 0.0 ? radius : 1.0};
}

} // namespace

std::string_view classificationName(Classification classification)
{
    return classification == Classification::Dynamic ? "dynamic" : "static";
}

std::optional<Classification> parseClassification(std::string_view name)
{
    if (name == "static")
        return Classification::Static;
    if (name == "dynamic")
        return Classification::Dynamic;
    return std::nullopt;
}

RelativeClipPlane relativeClipPlane(const ClipPlane& plane, const Bounds& bounds)
{
    const double length = glm::length(plane.normal);
    if (!(length > 0.0))
        throw std::invalid_argument("relativeClipPlane: the plane's normal is zero");
    const glm::dvec3 unit = plane.normal / length;
    const Support support = supportAlong(unit, bounds);
    return {plane.enabled, unit, plane.evaluate(support.centre) / length / support.extent};
}

ClipPlane absoluteClipPlane(const RelativeClipPlane& plane, const Bounds& bounds)
{
    const Support support = supportAlong(plane.normal, bounds);
    // n·c + d = distance · extent for the unit normal n.
    return {plane.enabled, plane.normal,
            plane.centreDistance * support.extent - glm::dot(plane.normal, support.centre)};
}

DocumentSettings documentDefaults(const Bounds& bounds, bool hasHistory)
{
    DocumentSettings settings;
    settings.trim.trimEnabled = true;
    settings.trim.rule = StaticRule::AlternatingBorder;
    settings.trim.clip = absoluteClipPlane(RelativeClipPlane{}, bounds);
    settings.classification = hasHistory ? Classification::Dynamic : Classification::Static;
    settings.trim.cap.spacing = capSpacing(settings, bounds);
    return settings;
}

double capSpacing(const DocumentSettings& settings, const Bounds& bounds)
{
    const double radius = bounds.valid() ? bounds.radius() : 0.0;
    return settings.capSpacingFraction * (radius > 0.0 ? radius : 1.0);
}

DocumentSettings refitClipPlanes(DocumentSettings settings, const Bounds& from, const Bounds& to)
{
    for (int i = 0; i < kMaxClipPlanes; ++i) {
        ClipPlane& plane = settings.trim.clipPlane(i);
        plane = absoluteClipPlane(relativeClipPlane(plane, from), to);
    }
    settings.trim.cap.spacing = capSpacing(settings, to);
    return settings;
}

StoredViewSettings storedViewSettings(const DocumentSettings& settings, const Bounds& bounds)
{
    StoredViewSettings stored;
    stored.trimEnabled = settings.trim.trimEnabled;
    stored.classification = settings.classification;
    for (int i = 0; i < kMaxClipPlanes; ++i)
        stored.clips[std::size_t(i)] = relativeClipPlane(settings.trim.clipPlane(i), bounds);
    stored.capEnabled = settings.trim.cap.enabled;
    stored.capPattern = settings.trim.cap.pattern;
    stored.capSpacingFraction = settings.capSpacingFraction;
    stored.highlight = settings.trim.highlight;
    stored.transparency = settings.trim.transparency;
    return stored;
}

DocumentSettings documentSettings(const StoredViewSettings& stored, StaticRule rule, const Bounds& bounds)
{
    DocumentSettings settings;
    settings.trim.trimEnabled = stored.trimEnabled;
    settings.trim.rule = rule;
    settings.classification = stored.classification;
    for (int i = 0; i < kMaxClipPlanes; ++i)
        settings.trim.clipPlane(i) = absoluteClipPlane(stored.clips[std::size_t(i)], bounds);
    settings.trim.cap.enabled = stored.capEnabled;
    settings.trim.cap.pattern = stored.capPattern;
    settings.capSpacingFraction = stored.capSpacingFraction;
    settings.trim.cap.spacing = capSpacing(settings, bounds);
    settings.trim.highlight = stored.highlight;
    settings.trim.transparency = stored.transparency;
    return settings;
}

} // namespace trimlab::timeline
