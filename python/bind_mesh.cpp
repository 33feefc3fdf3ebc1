#include "python/array_convert.h"
#include "python/bindings.h"
#include "python/python_errors.h"
#include "python/python_progress.h"

#include "core/catalog/scene_source.h"
#include "core/mesh/mesh_export.h"
#include "core/mesh/mesh_validation.h"
#include "core/scene/world_geometry.h"
#include "core/trim/hole_closing.h"
#include "core/trim/winding_number.h"
#include "core/util/parallel_for.h"

#include <pybind11/stl.h>

namespace trimlab::python {

namespace {

py::tuple objectArrays(const SceneObject& object)
{
    std::vector<glm::uvec3> triangles = object.mesh.triangles;
    return py::make_tuple(pointsArray(worldPositions(object)), trianglesArray(std::move(triangles)));
}

py::tuple load(const std::string& source)
{
    const LoadedScene loaded = loadScene(source);
    if (loaded.scene.objects.size() != 1)
        throw InputError(source + " holds " + std::to_string(loaded.scene.objects.size()) +
                         " objects; load_scene returns each of them");
    return objectArrays(loaded.scene.objects.front());
}

py::list loadSceneObjects(const std::string& source)
{
    const LoadedScene loaded = loadScene(source);
    py::list objects;
    for (const SceneObject& object : loaded.scene.objects)
        objects.append(objectArrays(object));
    return objects;
}

void save(const std::string& path, const py::object& vertices, const py::object& triangles, const std::string& comment)
{
    const TriangleMesh mesh = meshFromArrays(vertices, triangles);
    if (!isMeshExportPath(path))
        throw InputError(path + ": unknown mesh format (use " + meshExportFormatsText() + ")");
    try {
        py::gil_scoped_release release;
        saveTriangleMesh(path, mesh, comment);
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    } catch (const std::runtime_error& e) {
        throw MeshSaveError(e.what());
    }
}

template <class T>
py::dict defects(const DefectSamples<T>& samples)
{
    py::list first;
    for (const T& item : samples.first) {
        if constexpr (std::is_same_v<T, MeshEdge>)
            first.append(py::make_tuple(item.a, item.b));
        else
            first.append(item);
    }
    py::dict d;
    d["count"] = samples.count;
    d["first"] = first;
    return d;
}

py::dict reportDict(const MeshValidationReport& r, const std::string& name)
{
    py::dict d;
    d["vertices"] = r.vertexCount;
    d["triangles"] = r.triangleCount;
    d["edges"] = r.edgeCount;
    d["components"] = r.componentCount;
    d["bounds"] = r.bounds.valid()
                      ? py::object(py::make_tuple(py::make_tuple(r.bounds.min.x, r.bounds.min.y, r.bounds.min.z),
                                                  py::make_tuple(r.bounds.max.x, r.bounds.max.y, r.bounds.max.z)))
                      : py::object(py::none());
    d["euler_characteristic"] = r.eulerCharacteristic ? py::object(py::int_(*r.eulerCharacteristic)) : py::none();
    d["genus"] = r.genus ? py::object(py::int_(*r.genus)) : py::none();
    d["signed_volume"] = r.signedVolume;
    d["closed"] = r.closed();
    d["manifold"] = r.manifold();
    d["trimmable"] = r.trimmable();
    d["trim_unavailable_reason"] = r.trimUnavailableReason();
    py::dict found;
    found["out_of_range_faces"] = defects(r.outOfRangeFaces);
    found["non_finite_vertices"] = defects(r.nonFiniteVertices);
    found["degenerate_faces"] = defects(r.degenerateFaces);
    found["unreferenced_vertices"] = defects(r.unreferencedVertices);
    found["boundary_edges"] = defects(r.boundaryEdges);
    found["non_manifold_edges"] = defects(r.nonManifoldEdges);
    found["inconsistent_edges"] = defects(r.inconsistentEdges);
    found["unbalanced_edges"] = defects(r.unbalancedEdges);
    found["non_manifold_vertices"] = defects(r.nonManifoldVertices);
    d["defects"] = found;
    d["text"] = formatReport(r, name);
    return d;
}

py::dict info(const py::object& vertices, const py::object& triangles, const std::string& name)
{
    TriangleMesh mesh;
    mesh.positions = positionsFromArray(vertices, "V");
    mesh.triangles = trianglesFromArray(triangles, mesh.positions.size(), "F", false);
    MeshValidationReport report;
    {
        py::gil_scoped_release release;
        report = validateMesh(mesh);
    }
    return reportDict(report, name);
}

py::array_t<double> windingNumbers(const py::object& vertices, const py::object& triangles, const py::object& points,
                                   unsigned threads, const py::object& progress)
{
    Scene scene;
    scene.objects.push_back({"mesh", meshFromArrays(vertices, triangles), glm::dmat4(1.0)});
    const std::vector<glm::dvec3> queries = pointsFromArray(points, "points");
    std::vector<double> result = runWithProgress(progress, [&](const TaskControl& control) {
        std::vector<double> w(queries.size());
        parallelFor(
            queries.size(), threads, [&](std::size_t i) { w[i] = solidAngleWindingNumber(scene, queries[i]); }, control,
            "winding numbers");
        return w;
    });
    return vectorArray(std::move(result));
}

py::tuple closeHolesArrays(const py::object& vertices, const py::object& triangles)
{
    const TriangleMesh mesh = meshFromArrays(vertices, triangles);
    TriangleMesh closed;
    HoleClosing closing;
    try {
        py::gil_scoped_release release;
        closed = closedMesh(mesh, &closing);
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
    warnOfCrossingFans(closing);
    return meshArrays(std::move(closed));
}

py::list demoSources()
{
    py::list names;
    for (const DemoEntry& demo : builtInDemos())
        names.append(demo.source);
    return names;
}

constexpr const char* kLoadDoc = R"doc(load(source) -> (V, F)

Reads one mesh: a file (OBJ, OFF, PLY, STL, glTF/GLB, each optionally .gz), a built-in
demo ("demo:pushed-sphere", see demos()), a NURBS file or a .trimlab project with one
object. V is an (n, 3) float64 array (world space), F an (m, 3) int32 array of
counter-clockwise triangles.

Raises MeshLoadError naming the file, line and element ("cube.obj:12: face references
vertex 9, but the file has only 8 vertices"); InputError for an unknown demo or a source
of several objects (use load_scene).)doc";

constexpr const char* kLoadSceneDoc = R"doc(load_scene(source) -> list of (V, F)

Every object of a source, in world space, in the order of their ids (the ids CSG
expressions name). Raises as load().)doc";

constexpr const char* kSaveDoc = R"doc(save(path, V, F, comment="") -> None

Writes the mesh in the format its extension names: .obj, .ply (binary), .stl (binary),
.gltf (embedded buffer) or .glb, through a temporary file and a rename. V: (n, 3) real,
F: (m, 3) integer array of indices into V.

Raises InputError for bad arrays or an unknown extension, MeshSaveError when the file
cannot be written.)doc";

constexpr const char* kInfoDoc = R"doc(info(V, F, name="mesh") -> dict

The validation report `trimlab info` prints: counts ("vertices", "triangles", "edges",
"components"), "bounds" ((min, max) or None), "euler_characteristic" and "genus" (None
unless closed manifold), "signed_volume", "closed", "manifold", "trimmable",
"trim_unavailable_reason" ("" when trimmable), "defects" (each {"count", "first"}: the
first vertices, faces or (a, b) edges) and "text" (the report as the command line
prints it). Indices beyond V are counted as out-of-range faces, not refused.)doc";

constexpr const char* kWindingDoc = R"doc(winding_numbers(V, F, points, threads=0, progress=None) -> ndarray

The generalized winding number of each point (p, 3) with respect to the mesh: the signed
solid angle its triangles subtend, / 4π — an integer away from a closed surface (1 inside
an outward-oriented sphere), ill-conditioned on it. Returns a (p,) float64 array.
threads: 0 = every core. The GIL is released; progress(stage, done, total) is called
between points, an exception it raises stops the work and reaches the caller.)doc";

constexpr const char* kCloseHolesDoc = R"doc(close_holes(V, F) -> (V, F)

The mesh with each hole closed by a fan: one new vertex per boundary loop (appended to V,
at the centroid of the loop's corners) and a triangle from each loop edge to it (appended
to F, oriented like the mesh), as `trimlab render --close-holes` and Edit > Close Holes
do, so that the trim rules apply to an open mesh. A closed mesh comes back unchanged.

Raises InputError when the boundary does not form loops. A fan that crosses the surface
is applied with a RuntimeWarning naming the hole and the triangle: the trim may be wrong
between them.)doc";

} // namespace

void bindMesh(py::module_& m)
{
    m.def("load", &load, py::arg("source"), kLoadDoc);
    m.def("load_scene", &loadSceneObjects, py::arg("source"), kLoadSceneDoc);
    m.def("close_holes", &closeHolesArrays, py::arg("V"), py::arg("F"), kCloseHolesDoc);
    m.def("save", &save, py::arg("path"), py::arg("V"), py::arg("F"), py::arg("comment") = "", kSaveDoc);
    m.def("info", &info, py::arg("V"), py::arg("F"), py::arg("name") = "mesh", kInfoDoc);
    m.def("winding_numbers", &windingNumbers, py::arg("V"), py::arg("F"), py::arg("points"), py::kw_only(),
          py::arg("threads") = 0u, py::arg("progress") = py::none(), kWindingDoc);
    m.def("demos", &demoSources, "demos() -> list of str\n\nThe built-in demo sources load() opens.");
}

} // namespace trimlab::python
