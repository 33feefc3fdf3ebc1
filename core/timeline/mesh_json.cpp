#include "core/timeline/mesh_json.h"

#include "core/io/json_fields.h"
#include "core/timeline/binary_array.h"

namespace trimlab::timeline {

using io::fieldPath;
using io::JsonPathError;
using io::requiredField;
using io::requireObject;

using nlohmann::json;

json meshJson(const TriangleMesh& mesh)
{
    std::vector<std::uint32_t> indices;
    indices.reserve(mesh.triangles.size() * 3);
    for (const glm::uvec3& t : mesh.triangles)
        indices.insert(indices.end(), {t.x, t.y, t.z});
    return json{{"positions", positionArrayJson(mesh.positions)}, {"triangles", uint32ArrayJson(indices)}};
}

TriangleMesh readMesh(const json& value, const std::string& path)
{
    requireObject(value, path);
    TriangleMesh mesh;
    mesh.positions = readPositionArray(requiredField(value, "positions", path), fieldPath(path, "positions"));
    const std::string trianglesPath = fieldPath(path, "triangles");
    const std::vector<std::uint32_t> indices = readUint32Array(requiredField(value, "triangles", path), trianglesPath);
    if (indices.size() % 3 != 0)
        throw JsonPathError(fieldPath(trianglesPath, "count"),
                            "must be a multiple of 3, not " + std::to_string(indices.size()));
    mesh.triangles.resize(indices.size() / 3);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        mesh.triangles[t] = {indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]};
    return mesh;
}

} // namespace trimlab::timeline
