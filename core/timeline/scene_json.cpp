#include "core/timeline/scene_json.h"

#include "core/io/json_fields.h"
#include "core/scene/world_geometry.h"
#include "core/timeline/mesh_json.h"
#include "core/trim/csg_expression.h"
#include "core/trim/static_rule.h"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <stdexcept>

namespace trimlab::timeline {

using io::fieldPath;
using io::finiteNumber;
using io::indexPath;
using io::JsonPathError;
using io::optionalField;
using io::requireArray;
using io::requiredField;
using io::requireObject;
using io::stringValue;

using nlohmann::json;

namespace {

// Why `model` cannot place an object ("" when it can): finite, affine (last row 0 0 0 1)
// and orientation preserving (SceneObject's requirement: facing and winding keep their
// meaning).
std::string modelMatrixProblem(const glm::dmat4& model)
{
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(model[c][r]))
                return "has a non-finite entry";
    if (model[0][3] != 0.0 || model[1][3] != 0.0 || model[2][3] != 0.0 || model[3][3] != 1.0)
        return "is not affine (its last row must be 0 0 0 1)";
    if (!(glm::determinant(glm::dmat3(model)) > 0.0))
        return "does not preserve orientation (its determinant is not positive): a mirror would turn the object "
               "inside out";
    return {};
}

std::string triangleIndexProblem(const TriangleMesh& mesh)
{
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (mesh.triangles[t][k] >= mesh.positions.size())
                return "triangle " + std::to_string(t) + " refers to vertex " + std::to_string(mesh.triangles[t][k]) +
                       ", but the mesh has " + std::to_string(mesh.positions.size());
    return {};
}

json matrixJson(const glm::dmat4& model)
{
    json values = json::array();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            values.push_back(model[c][r]);
    return values;
}

glm::dmat4 readMatrix(const json& value, const std::string& path)
{
    requireArray(value, path);
    if (value.size() != 16)
        throw JsonPathError(path, "must hold 16 numbers (column-major), not " + std::to_string(value.size()));
    glm::dmat4 model(1.0);
    for (int i = 0; i < 16; ++i)
        model[i / 4][i % 4] = finiteNumber(value[std::size_t(i)], indexPath(path, std::size_t(i)));
    if (const std::string problem = modelMatrixProblem(model); !problem.empty())
        throw JsonPathError(path, problem);
    return model;
}

SceneObject readObject(const json& item, const std::string& path)
{
    requireObject(item, path);
    SceneObject object;
    object.name = stringValue(requiredField(item, "name", path), fieldPath(path, "name"));
    object.mesh = readMesh(requiredField(item, "mesh", path), fieldPath(path, "mesh"));
    if (const std::string problem = triangleIndexProblem(object.mesh); !problem.empty())
        throw JsonPathError(fieldPath(path, "mesh"), problem);
    object.modelMatrix = readMatrix(requiredField(item, "model_matrix", path), fieldPath(path, "model_matrix"));
    if (const std::string problem = placementProblem(object); !problem.empty())
        throw JsonPathError(fieldPath(path, "model_matrix"), "object '" + object.name + "': " + problem);
    return object;
}

std::optional<StaticRule> readObjectRule(const json& item, std::size_t id, const std::string& path)
{
    const json* value = optionalField(item, "rule");
    if (!value)
        return std::nullopt;
    const std::string rulePath = fieldPath(path, "rule");
    if (id >= std::size_t(kMaxCsgOperands))
        throw JsonPathError(rulePath, "only objects 0 to " + std::to_string(kMaxCsgOperands - 1) +
                                          " take part in CSG and may have their own rule");
    const std::string name = stringValue(*value, rulePath);
    const std::optional<StaticRule> rule = parseStaticRule(name);
    if (!rule)
        throw JsonPathError(rulePath, "unknown static rule '" + name + "' (known: " + staticRuleNamesHelp() + ")");
    return rule;
}

} // namespace

bool operator==(const ProjectScene& a, const ProjectScene& b)
{
    if (a.objects.size() != b.objects.size() || !(a.csg == b.csg))
        return false;
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        const SceneObject& x = a.objects[i];
        const SceneObject& y = b.objects[i];
        if (x.name != y.name || x.modelMatrix != y.modelMatrix || x.mesh.positions != y.mesh.positions ||
            x.mesh.triangles != y.mesh.triangles)
            return false;
    }
    return true;
}

json sceneJson(const ProjectScene& scene)
{
    if (scene.objects.empty() || scene.objects.size() > Scene::maxObjects)
        throw std::invalid_argument("projectJson: a scene holds 1 to " + std::to_string(Scene::maxObjects) +
                                    " objects, not " + std::to_string(scene.objects.size()));
    json objects = json::array();
    for (std::size_t id = 0; id < scene.objects.size(); ++id) {
        const SceneObject& object = scene.objects[id];
        const std::string what = "projectJson: object " + std::to_string(id) + " ('" + object.name + "') ";
        if (const std::string problem = modelMatrixProblem(object.modelMatrix); !problem.empty())
            throw std::invalid_argument(what + "model matrix " + problem);
        if (const std::string problem = triangleIndexProblem(object.mesh); !problem.empty())
            throw std::invalid_argument(what + "mesh: " + problem);
        json item{
            {"name", object.name}, {"mesh", meshJson(object.mesh)}, {"model_matrix", matrixJson(object.modelMatrix)}};
        if (id < scene.csg.objectRules.size() && scene.csg.objectRules[id])
            item["rule"] = ruleName(*scene.csg.objectRules[id]);
        objects.push_back(std::move(item));
    }
    json document{{"objects", std::move(objects)}};
    if (scene.csg.enabled()) {
        if (csgMaxObjectId(scene.csg.expression) >= int(scene.objects.size()))
            throw std::invalid_argument("projectJson: the CSG expression names object " +
                                        std::to_string(csgMaxObjectId(scene.csg.expression)) + " of " +
                                        std::to_string(scene.objects.size()));
        document["csg"] = formatCsgExpression(scene.csg.expression);
    }
    return document;
}

ProjectScene readScene(const json& value, const std::string& path)
{
    requireObject(value, path);
    const std::string objectsPath = fieldPath(path, "objects");
    const json& objects = requiredField(value, "objects", path);
    requireArray(objects, objectsPath);
    if (objects.empty() || objects.size() > Scene::maxObjects)
        throw JsonPathError(objectsPath, "must hold 1 to " + std::to_string(Scene::maxObjects) + " objects, not " +
                                             std::to_string(objects.size()));
    ProjectScene scene;
    for (std::size_t id = 0; id < objects.size(); ++id) {
        const std::string objectPath = indexPath(objectsPath, id);
        scene.objects.push_back(readObject(objects[id], objectPath));
        if (std::optional<StaticRule> rule = readObjectRule(objects[id], id, objectPath))
            scene.csg.objectRules[id] = *rule;
    }
    if (const json* csg = optionalField(value, "csg")) {
        const std::string csgPath = fieldPath(path, "csg");
        const std::string text = stringValue(*csg, csgPath);
        std::string error;
        const std::optional<CsgExpression> expression = parseCsgExpression(text, &error);
        if (!expression)
            throw JsonPathError(csgPath, error);
        if (csgMaxObjectId(*expression) >= int(scene.objects.size()))
            throw JsonPathError(csgPath, "names object " + std::to_string(csgMaxObjectId(*expression)) +
                                             ", but the scene has " + std::to_string(scene.objects.size()));
        scene.csg.expression = *expression;
    }
    return scene;
}

} // namespace trimlab::timeline
