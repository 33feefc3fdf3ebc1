#pragma once
/// \file
/// The command-line options that compose a scene from several sources, shared by
/// `render`, `bench` and `info`: the sources in order (object ids count across them, see
/// loadScenes), --object-transform ID=... for each object's placement, and the rule
/// options (--rule, --csg, --object-rule) parsed into TrimSettings. Every parser returns
/// the one-line error a user sees (exit code 2), or nothing.

#include "core/catalog/scene_source.h"
#include "core/scene/object_transform.h"
#include "core/scene/scene.h"
#include "core/trim/trim_settings.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <string>
#include <vector>

class QCommandLineParser;

namespace trimlab::app {

/// One --object-transform: the object's placement becomes `transform` (as in the Scene
/// panel's fields, replacing whatever placement the file gave it).
struct ObjectTransformOption {
    int object = 0;
    ObjectTransform transform;
};

/// The help text of --object-transform.
[[nodiscard]] QString objectTransformHelp();

/// Parses "ID=TX,TY,TZ[,RX,RY,RZ[,S]]": translation, then optionally rotation angles in
/// degrees about x, y, z (applied in that order) and a uniform scale > 0.
[[nodiscard]] std::optional<QString> parseObjectTransform(const QString& text, std::vector<ObjectTransformOption>& out);

/// --close-holes on a loaded scene: closes the holes of its objects (closeSceneHoles,
/// which throws MeshLoadError naming the object when a boundary forms no loops) and notes
/// on stderr what was closed ("closed 1 hole of 20 edges in horse.obj"), a fan that
/// crosses the surface included.
void closeHolesNoted(LoadedScene& loaded);

/// Sets each listed object's model matrix; an error naming the option when an id is not
/// an object of `scene`.
[[nodiscard]] std::optional<QString> applyObjectTransforms(const std::vector<ObjectTransformOption>& transforms,
                                                           Scene& scene);

/// The positional arguments as sources; an error when there are none.
[[nodiscard]] std::optional<QString> takeSources(const QStringList& positional, const QString& verb,
                                                 std::vector<std::string>& sources);

/// --rule: a static rule name or "none" (trimming off).
[[nodiscard]] std::optional<QString> parseRuleOption(const QString& text, TrimSettings& trim);
/// Every --clip of `parser` (render and trim) into trim's clipping set (parseClipSet), or
/// the "--clip: ..." error; nothing when none was given.
[[nodiscard]] std::optional<QString> parseClipOptions(const QCommandLineParser& parser, TrimSettings& trim);
/// --object-rule ID=RULE.
[[nodiscard]] std::optional<QString> parseObjectRuleOption(const QString& text, CsgSettings& csg);
/// --csg EXPRESSION.
[[nodiscard]] std::optional<QString> parseCsgOption(const QString& text, CsgSettings& csg);

/// A scene project's saved CSG where the command line gave none: the object rules of the
/// ids no --object-rule named, and the expression unless --csg gave one
/// (`expressionGiven`) or there is no rule to combine (`trimEnabled` false).
void adoptSavedCsg(const LoadedScene& loaded, CsgSettings& csg, bool expressionGiven, bool trimEnabled);

/// After loading: --csg operands and --object-rule ids must be objects of the scene.
[[nodiscard]] std::optional<QString> checkObjectIds(const CsgSettings& csg, std::size_t objectCount);

} // namespace trimlab::app
