#include "python/array_convert.h"

#include "python/python_errors.h"

#include <cstring>
#include <limits>

namespace trimlab::python {

namespace {

std::string shapeText(const py::array& array)
{
    std::string text = "(";
    for (py::ssize_t i = 0; i < array.ndim(); ++i)
        text += (i ? ", " : "") + std::to_string(array.shape(i));
    return text + (array.ndim() == 1 ? ",)" : ")");
}

py::array asArray(py::handle object, const char* name, const char* wanted)
{
    py::array array = py::array::ensure(object);
    if (!array)
        throw InputError(std::string(name) + " must be " + wanted + ", got " +
                         std::string(py::str(py::type::handle_of(object).attr("__name__"))));
    return array;
}

// A real (or integer) array of the given rank whose last axis has three entries, as
// C-contiguous float64 (in place when it already is).
py::array_t<double, py::array::c_style | py::array::forcecast> realTriples(py::handle object, const char* name,
                                                                           int rank, const char* wanted)
{
    const py::array array = asArray(object, name, wanted);
    const char kind = array.dtype().kind();
    const bool numeric = kind == 'f' || kind == 'i' || kind == 'u';
    if (!numeric || array.ndim() != rank || array.shape(rank - 1) != 3)
        throw InputError(std::string(name) + " must be " + wanted + ", got shape " + shapeText(array) + " of dtype " +
                         std::string(py::str(array.dtype())));
    return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
}

std::string faceText(const char* name, py::ssize_t face, const std::int64_t* corners)
{
    return std::string(name) + "[" + std::to_string(face) + "] = (" + std::to_string(corners[0]) + ", " +
           std::to_string(corners[1]) + ", " + std::to_string(corners[2]) + ")";
}

} // namespace

std::vector<glm::vec3> positionsFromArray(py::handle object, const char* name)
{
    const auto array = realTriples(object, name, 2, "an (n, 3) array of float64");
    const auto values = array.unchecked<2>();
    std::vector<glm::vec3> positions(std::size_t(values.shape(0)));
    for (py::ssize_t i = 0; i < values.shape(0); ++i)
        positions[std::size_t(i)] = glm::vec3(float(values(i, 0)), float(values(i, 1)), float(values(i, 2)));
    return positions;
}

std::vector<glm::dvec3> pointsFromArray(py::handle object, const char* name)
{
    const auto array = realTriples(object, name, 2, "a (p, 3) array of float64");
    std::vector<glm::dvec3> points(std::size_t(array.shape(0)));
    static_assert(sizeof(glm::dvec3) == 3 * sizeof(double));
    if (!points.empty())
        std::memcpy(points.data(), array.data(), points.size() * sizeof(glm::dvec3));
    return points;
}

std::vector<glm::uvec3> trianglesFromArray(py::handle object, std::size_t vertexCount, const char* name,
                                           bool checkRange)
{
    const char* wanted = "an (m, 3) integer array";
    const py::array array = asArray(object, name, wanted);
    const char kind = array.dtype().kind();
    if ((kind != 'i' && kind != 'u') || array.ndim() != 2 || array.shape(1) != 3)
        throw InputError(std::string(name) + " must be " + wanted + ", got shape " + shapeText(array) + " of dtype " +
                         std::string(py::str(array.dtype())));
    const auto indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
    const auto values = indices.unchecked<2>();
    std::vector<glm::uvec3> triangles(std::size_t(values.shape(0)));
    constexpr std::int64_t kMaxIndex = std::numeric_limits<std::int32_t>::max();
    for (py::ssize_t f = 0; f < values.shape(0); ++f) {
        const std::int64_t* corners = values.data(f, 0);
        for (int c = 0; c < 3; ++c) {
            if (corners[c] < 0 || corners[c] > kMaxIndex)
                throw InputError(faceText(name, f, corners) + ": index " + std::to_string(corners[c]) +
                                 " is negative or too large");
            if (checkRange && std::uint64_t(corners[c]) >= vertexCount)
                throw InputError(faceText(name, f, corners) + ": vertex " + std::to_string(corners[c]) +
                                 " does not exist (V has " + std::to_string(vertexCount) + " vertices)");
        }
        triangles[std::size_t(f)] = glm::uvec3(unsigned(corners[0]), unsigned(corners[1]), unsigned(corners[2]));
    }
    return triangles;
}

TriangleMesh meshFromArrays(py::handle vertices, py::handle triangles)
{
    TriangleMesh mesh;
    mesh.positions = positionsFromArray(vertices, "V");
    mesh.triangles = trianglesFromArray(triangles, mesh.positions.size(), "F");
    return mesh;
}

std::vector<std::vector<glm::vec3>> posesFromArray(py::handle object, const char* name)
{
    const auto array = realTriples(object, name, 3, "a (k, n, 3) array of float64 poses");
    const auto values = array.unchecked<3>();
    std::vector<std::vector<glm::vec3>> poses(std::size_t(values.shape(0)));
    for (py::ssize_t k = 0; k < values.shape(0); ++k) {
        std::vector<glm::vec3>& pose = poses[std::size_t(k)];
        pose.resize(std::size_t(values.shape(1)));
        for (py::ssize_t i = 0; i < values.shape(1); ++i)
            pose[std::size_t(i)] = glm::vec3(float(values(k, i, 0)), float(values(k, i, 1)), float(values(k, i, 2)));
    }
    return poses;
}

py::array_t<double> positionsArray(const std::vector<glm::vec3>& positions)
{
    py::array_t<double> array({py::ssize_t(positions.size()), py::ssize_t(3)});
    auto out = array.mutable_unchecked<2>();
    for (std::size_t i = 0; i < positions.size(); ++i)
        for (int c = 0; c < 3; ++c)
            out(py::ssize_t(i), c) = double(positions[i][c]);
    return array;
}

py::array_t<double> pointsArray(std::vector<glm::dvec3>&& points)
{
    const py::ssize_t count = py::ssize_t(points.size());
    glm::dvec3* data = nullptr;
    py::capsule owner = ownerOf(std::move(points), data);
    return py::array_t<double>({count, py::ssize_t(3)}, {py::ssize_t(sizeof(glm::dvec3)), py::ssize_t(sizeof(double))},
                               reinterpret_cast<const double*>(data), owner);
}

py::array_t<std::int32_t> trianglesArray(std::vector<glm::uvec3>&& triangles)
{
    static_assert(sizeof(glm::uvec3) == 3 * sizeof(std::int32_t));
    const py::ssize_t count = py::ssize_t(triangles.size());
    glm::uvec3* data = nullptr;
    py::capsule owner = ownerOf(std::move(triangles), data);
    return py::array_t<std::int32_t>({count, py::ssize_t(3)},
                                     {py::ssize_t(sizeof(glm::uvec3)), py::ssize_t(sizeof(std::int32_t))},
                                     reinterpret_cast<const std::int32_t*>(data), owner);
}

py::tuple meshArrays(TriangleMesh&& mesh)
{
    py::array_t<double> vertices = positionsArray(mesh.positions);
    return py::make_tuple(vertices, trianglesArray(std::move(mesh.triangles)));
}

namespace {

template <class Vec3>
py::array_t<double> posesArrayOf(const std::vector<std::vector<Vec3>>& poses)
{
    const py::ssize_t n = poses.empty() ? 0 : py::ssize_t(poses.front().size());
    py::array_t<double> array({py::ssize_t(poses.size()), n, py::ssize_t(3)});
    auto out = array.mutable_unchecked<3>();
    for (std::size_t k = 0; k < poses.size(); ++k)
        for (std::size_t i = 0; i < poses[k].size(); ++i)
            for (int c = 0; c < 3; ++c)
                out(py::ssize_t(k), py::ssize_t(i), c) = double(poses[k][i][c]);
    return array;
}

} // namespace

py::array_t<double> posesArray(const std::vector<std::vector<glm::vec3>>& poses)
{
    return posesArrayOf(poses);
}

py::array_t<double> posesArray(const std::vector<std::vector<glm::dvec3>>& poses)
{
    return posesArrayOf(poses);
}

} // namespace trimlab::python
