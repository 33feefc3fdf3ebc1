// A document's view settings (core/timeline/view_settings.h): clipping planes relative to
// the bounds, the defaults of a new document, refitting to grown bounds, and the project
// file's "view_settings" object — round trips and typed errors.
#include "project_load_error.h"
#include "tst_timeline_fixtures.h"

#include "core/timeline/project_file.h"
#include "core/timeline/view_settings.h"
#include "core/timeline/view_settings_json.h"

#include <QtTest>

#include <glm/geometric.hpp>

using namespace trimlab;
using namespace trimlab::timeline;
using trimlab::test::gridMesh;

namespace {

Bounds box(glm::dvec3 min, glm::dvec3 max)
{
    Bounds bounds;
    bounds.extend(min);
    bounds.extend(max);
    return bounds;
}

// A settings value with every field away from its default.
DocumentSettings unusualSettings(const Bounds& bounds)
{
    DocumentSettings settings = documentDefaults(bounds, true);
    settings.trim.trimEnabled = false;
    settings.trim.rule = StaticRule::Parity;
    settings.classification = Classification::Static;
    settings.trim.clip = ClipPlane{true, {1.0, 0.0, 0.0}, -0.25};
    settings.trim.clipPlane(3) = ClipPlane{true, {0.0, -2.0, 0.0}, 0.5};
    settings.trim.cap.enabled = true;
    settings.trim.cap.pattern = CapPattern::Striped;
    settings.capSpacingFraction = 0.125;
    settings.trim.cap.spacing = capSpacing(settings, bounds);
    settings.trim.highlight.collisions = true;
    settings.trim.transparency.enabled = true;
    settings.trim.transparency.display = TrimDisplay::Opaque;
    settings.trim.transparency.layerAlpha = 0.75;
    settings.trim.transparency.ghostAlpha = 0.5;
    settings.trim.transparency.density = 2.0;
    settings.trim.transparency.fresnelExponent = 3.0;
    return settings;
}

void compareNearly(const ClipPlane& actual, const ClipPlane& expected)
{
    const double scale = glm::length(expected.normal) / glm::length(actual.normal);
    QCOMPARE(actual.enabled, expected.enabled);
    QVERIFY(glm::length(actual.normal * scale - expected.normal) < 1e-12);
    QVERIFY(std::abs(actual.offset * scale - expected.offset) < 1e-12);
}

} // namespace

class ViewSettingsTest : public QObject {
    Q_OBJECT
private slots:
    void relativePlanesKeepTheirPlaceInTheBounds();
    void defaultsCutThroughTheCentreOfAnyScene();
    void historiesDefaultToTheDynamicClassification();
    void refitGrowsABoxWithTheScene();
    void capSpacingFollowsTheRadius();
    void storedSettingsRoundTrip();
    void jsonRoundTripsEveryField();
    void projectFilesKeepTheSettings();
    void filesWithoutSettingsHaveNone();
    void badSettingsAreRefusedWithTheirPath();
};

void ViewSettingsTest::relativePlanesKeepTheirPlaceInTheBounds()
{
    const Bounds bounds = box({0.21, -1.0, 3.0}, {0.59, 1.5, 4.0});
    const ClipPlane plane{true, {0.0, 0.0, -2.0}, 7.0};
    const RelativeClipPlane relative = relativeClipPlane(plane, bounds);
    QVERIFY(std::abs(glm::length(relative.normal) - 1.0) < 1e-15);
    compareNearly(absoluteClipPlane(relative, bounds), plane);
    // Through the centre: distance 0; on the face the normal points away from: 1; on the
    // opposite face: −1.
    const ClipPlane centre{true, {1.0, 0.0, 0.0}, -bounds.center().x};
    QVERIFY(std::abs(relativeClipPlane(centre, bounds).centreDistance) < 1e-12);
    const ClipPlane lowFace{true, {1.0, 0.0, 0.0}, -bounds.min.x};
    QVERIFY(std::abs(relativeClipPlane(lowFace, bounds).centreDistance - 1.0) < 1e-12);
    const ClipPlane highFace{true, {2.0, 0.0, 0.0}, -2.0 * bounds.max.x};
    QVERIFY(std::abs(relativeClipPlane(highFace, bounds).centreDistance + 1.0) < 1e-12);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)relativeClipPlane(ClipPlane{true, {0, 0, 0}, 1.0}, bounds));
}

// A newly opened mesh far from the origin (the samba animation lies at x 0.21 to 0.59) is
// not cut away by the prepared plane: it passes through the mesh's centre.
void ViewSettingsTest::defaultsCutThroughTheCentreOfAnyScene()
{
    const Bounds bounds = box({0.21, 0.0, -0.1}, {0.59, 1.7, 0.3});
    const DocumentSettings settings = documentDefaults(bounds, false);
    QVERIFY(settings.trim.trimEnabled);
    QCOMPARE(settings.trim.rule, StaticRule::AlternatingBorder);
    QVERIFY(!settings.trim.clip.enabled);
    QVERIFY(std::abs(settings.trim.clip.evaluate(bounds.center())) < 1e-12);
    QVERIFY(!settings.trim.clipSet().anyEnabled());
    QVERIFY(!settings.trim.cap.enabled && !settings.trim.highlight.any() && !settings.trim.xray());
    QVERIFY(!settings.trim.csg.enabled());
}

void ViewSettingsTest::historiesDefaultToTheDynamicClassification()
{
    const Bounds bounds = box({-1, -1, -1}, {1, 1, 1});
    QCOMPARE(documentDefaults(bounds, false).classification, Classification::Static);
    QCOMPARE(documentDefaults(bounds, true).classification, Classification::Dynamic);
}

// A box of planes just around object 0 encloses the whole scene once another object
// widened the bounds (the added object is not hidden behind the first one's box).
void ViewSettingsTest::refitGrowsABoxWithTheScene()
{
    const Bounds first = box({-1, -1, -1}, {1, 1, 1});
    DocumentSettings settings = documentDefaults(first, false);
    settings.trim.setClipSet(ClipSet::box(first.min, first.max));
    const Bounds grown = box({-1, -1, -1}, {5, 3, 1});
    const DocumentSettings refit = refitClipPlanes(settings, first, grown);
    // Each plane lies on a face of the grown box: its corners are on the kept side.
    for (const glm::dvec3 corner : {grown.min, grown.max, glm::dvec3(5, -1, 1), glm::dvec3(-1, 3, -1)}) {
        for (const ClipPlane& plane : refit.trim.clipSet().planes)
            QVERIFY2(plane.evaluate(corner) > -1e-12, "a corner of the grown scene is clipped away");
    }
    const glm::dvec3 added(4.0, 2.0, 0.0);
    QVERIFY(!settings.trim.clipSet().keeps(added));
    QVERIFY(refit.trim.clipSet().keeps(added));
    // The same bounds change nothing.
    const DocumentSettings same = refitClipPlanes(settings, first, first);
    for (int i = 0; i < kMaxClipPlanes; ++i)
        compareNearly(same.trim.clipPlane(i), settings.trim.clipPlane(i));
}

void ViewSettingsTest::capSpacingFollowsTheRadius()
{
    DocumentSettings settings;
    settings.capSpacingFraction = 0.1;
    const Bounds small = box({-1, -1, -1}, {1, 1, 1});
    const Bounds large = box({-3, -3, -3}, {3, 3, 3});
    QVERIFY(std::abs(capSpacing(settings, small) - 0.1 * small.radius()) < 1e-15);
    QVERIFY(std::abs(capSpacing(settings, large) - 3.0 * capSpacing(settings, small)) < 1e-12);
    QVERIFY(std::abs(refitClipPlanes(settings, small, large).trim.cap.spacing - capSpacing(settings, large)) < 1e-15);
    QCOMPARE(capSpacing(settings, Bounds{}), 0.1); // no scene: the unit sphere
}

void ViewSettingsTest::storedSettingsRoundTrip()
{
    const Bounds bounds = box({0.2, -1.0, 3.0}, {0.6, 1.5, 4.0});
    const DocumentSettings settings = unusualSettings(bounds);
    const DocumentSettings back = documentSettings(storedViewSettings(settings, bounds), settings.trim.rule, bounds);
    QCOMPARE(back.trim.trimEnabled, settings.trim.trimEnabled);
    QCOMPARE(back.trim.rule, settings.trim.rule);
    QCOMPARE(back.classification, settings.classification);
    for (int i = 0; i < kMaxClipPlanes; ++i)
        compareNearly(back.trim.clipPlane(i), settings.trim.clipPlane(i));
    QCOMPARE(back.trim.cap, settings.trim.cap);
    QCOMPARE(back.capSpacingFraction, settings.capSpacingFraction);
    QCOMPARE(back.trim.highlight, settings.trim.highlight);
    QCOMPARE(back.trim.transparency, settings.trim.transparency);
}

void ViewSettingsTest::jsonRoundTripsEveryField()
{
    const Bounds bounds = box({0.2, -1.0, 3.0}, {0.6, 1.5, 4.0});
    const StoredViewSettings stored = storedViewSettings(unusualSettings(bounds), bounds);
    const nlohmann::json json = viewSettingsJson(stored);
    QCOMPARE(json.at("classification").get<std::string>(), std::string("static"));
    QCOMPARE(json.at("clips").size(), std::size_t(kMaxClipPlanes));
    QCOMPARE(readViewSettings(json, "view_settings"), stored);
    QCOMPARE(readViewSettings(nlohmann::json::object(), "view_settings"), StoredViewSettings{});
}

void ViewSettingsTest::projectFilesKeepTheSettings()
{
    const Timeline history(gridMesh(3), DynamicRule::ConstructiveAdditive);
    const Bounds bounds = box({0, 0, 0}, {1, 1, 0});
    ProjectExtras extras;
    extras.staticRule = StaticRule::Parity;
    extras.viewSettings = storedViewSettings(unusualSettings(bounds), bounds);
    extras.viewSettings->classification = Classification::Dynamic;
    const Project project = parseProject(projectJson(history, extras), "view.trimlab");
    QVERIFY(project.extras.viewSettings.has_value());
    QCOMPARE(*project.extras.viewSettings, *extras.viewSettings);
    QCOMPARE(project.extras, extras);
}

void ViewSettingsTest::filesWithoutSettingsHaveNone()
{
    const Timeline history(gridMesh(3), DynamicRule::ConstructiveAdditive);
    const Project project = parseProject(projectJson(history, ProjectExtras{}), "plain.trimlab");
    QVERIFY(!project.extras.viewSettings.has_value());
    // A missing field keeps its default.
    std::string text = projectJson(history, ProjectExtras{});
    text.insert(text.rfind('}'), ",\"view_settings\": {\"classification\": \"dynamic\"}");
    const Project partial = parseProject(text, "partial.trimlab");
    StoredViewSettings expected;
    expected.classification = Classification::Dynamic;
    QCOMPARE(*partial.extras.viewSettings, expected);
}

void ViewSettingsTest::badSettingsAreRefusedWithTheirPath()
{
    const Timeline history(gridMesh(3), DynamicRule::ConstructiveAdditive);
    const std::string plain = projectJson(history, ProjectExtras{});
    const auto withSettings = [&](const std::string& settings) {
        std::string text = plain;
        text.insert(text.rfind('}'), ",\"view_settings\": " + settings);
        return test::projectLoadError(text, "bad.trimlab");
    };
    struct Case {
        const char* settings;
        const char* where;
    };
    const Case cases[] = {
        {"3", "view_settings"},
        {"{\"classification\": \"sometimes\"}", "view_settings.classification"},
        {"{\"trim\": 1}", "view_settings.trim"},
        {"{\"clips\": [{\"normal\": [0, 0, 0]}]}", "view_settings.clips[0].normal"},
        {"{\"clips\": [{}, {}, {}, {}, {}, {}, {}]}", "view_settings.clips"},
        {"{\"cap\": {\"pattern\": \"dotted\"}}", "view_settings.cap.pattern"},
        {"{\"cap\": {\"spacing_fraction\": 0}}", "view_settings.cap.spacing_fraction"},
        {"{\"transparency\": {\"layer_alpha\": 2}}", "view_settings.transparency.layer_alpha"},
        {"{\"highlight\": {\"coplanar\": \"yes\"}}", "view_settings.highlight.coplanar"},
    };
    for (const Case& c : cases) {
        const ProjectFileError error = withSettings(c.settings);
        QVERIFY2(std::string(error.what()).find(c.where) != std::string::npos, error.what());
    }
}

QTEST_GUILESS_MAIN(ViewSettingsTest)
#include "tst_view_settings.moc"
