#include "python/scene_arguments.h"

#include "python/array_convert.h"
#include "python/python_errors.h"

#include "core/mesh/mesh_validation.h"
#include "core/trim/csg_expression.h"
#include "core/trim/csg_object_ids.h"
#include "core/trim/static_rule.h"

namespace trimlab::python {

namespace {

void addObject(LoadedScene& loaded, py::handle vertices, py::handle triangles)
{
    SceneObject object;
    object.name = "object " + std::to_string(loaded.scene.objects.size());
    object.mesh = meshFromArrays(vertices, triangles);
    loaded.reports.push_back(validateMesh(object.mesh));
    loaded.scene.objects.push_back(std::move(object));
}

StaticRule ruleNamed(const std::string& name, const std::string& what)
{
    const std::optional<StaticRule> rule = parseStaticRule(name);
    if (!rule)
        throw InputError("unknown " + what + " '" + name + "' (use " + staticRuleNamesHelp() + ")");
    return *rule;
}

// Ids beyond what CsgSettings holds cannot be stored to be checked; the others are checked
// with the command line's check once all are set.
void setObjectRule(CsgSettings& csg, long long id, py::handle name, std::size_t objectCount)
{
    if (name.is_none())
        return;
    if (id < 0 || id >= kMaxCsgOperands)
        throw InputError("rules " + csgObjectIdReason(int(id), objectCount));
    csg.objectRules[std::size_t(id)] = ruleNamed(py::str(name), "rule of object " + std::to_string(id));
}

} // namespace

LoadedScene sceneFromArguments(py::handle meshes, py::handle triangles)
{
    LoadedScene loaded;
    loaded.displayName = "mesh";
    if (!triangles.is_none()) {
        addObject(loaded, meshes, triangles);
        return loaded;
    }
    if (!py::isinstance<py::sequence>(meshes) || py::isinstance<py::str>(meshes))
        throw InputError("give V and F, or a list of (V, F) pairs");
    for (py::handle pair : meshes) {
        const py::sequence items = py::reinterpret_borrow<py::sequence>(pair);
        if (!py::isinstance<py::sequence>(pair) || py::len(items) != 2)
            throw InputError("each object must be a (V, F) pair");
        addObject(loaded, py::object(items[0]), py::object(items[1]));
    }
    if (loaded.scene.objects.empty() || loaded.scene.objects.size() > Scene::maxObjects)
        throw InputError("a scene has 1 to " + std::to_string(Scene::maxObjects) + " objects, got " +
                         std::to_string(loaded.scene.objects.size()));
    return loaded;
}

TrimSettings trimSettingsFromArguments(const std::string& rule, py::handle csg, py::handle rules,
                                       std::size_t objectCount)
{
    TrimSettings settings;
    settings.rule = ruleNamed(rule, "rule");
    if (!csg.is_none()) {
        const std::string text = py::str(csg);
        std::string error;
        const std::optional<CsgExpression> expression = parseCsgExpression(text, &error);
        if (!expression)
            throw InputError("csg '" + text + "': " + error);
        settings.csg.expression = *expression;
    }
    if (py::isinstance<py::dict>(rules)) {
        for (auto [id, name] : py::reinterpret_borrow<py::dict>(rules))
            setObjectRule(settings.csg, id.cast<long long>(), name, objectCount);
    } else if (!rules.is_none()) {
        long long id = 0;
        for (py::handle name : rules)
            setObjectRule(settings.csg, id++, name, objectCount);
    }
    if (const std::optional<CsgObjectIdProblem> problem = csgObjectIdOutsideScene(settings.csg, objectCount))
        throw InputError((problem->inExpression ? "csg " : "rules ") + csgObjectIdReason(problem->id, objectCount));
    return settings;
}

void requireTrimmable(const LoadedScene& loaded)
{
    if (!loaded.trimmable())
        throw NotTrimmableError("no inside to trim: " + loaded.trimUnavailableReason());
}

} // namespace trimlab::python
