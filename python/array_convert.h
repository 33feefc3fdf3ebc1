#pragma once
/// \file
/// NumPy arrays to TrimLab's geometry and back. Vertices travel as (n, 3) float64 arrays,
/// triangles as (m, 3) int32 arrays, points as (p, 3) float64 and animations as (k, n, 3)
/// float64 poses. Inputs of another numeric type are converted; a C-contiguous float64
/// input is read in place. Results own the C++ buffer they were computed in wherever its
/// layout is the array's (triangles, double points), so nothing is copied on the way out.
///
/// Every refusal is an InputError (python_errors.h) naming the argument, its shape or the
/// first bad element: "F must be an (m, 3) integer array, got shape (4,)",
/// "F[3] = (0, 1, 9): vertex 9 does not exist (V has 8 vertices)".

#include "core/mesh/triangle_mesh.h"

#include <glm/vec3.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

namespace trimlab::python {

namespace py = pybind11;

/// (n, 3) real array → float positions (rounded as TrimLab stores them). n ≥ 0.
[[nodiscard]] std::vector<glm::vec3> positionsFromArray(py::handle array, const char* name);
/// (p, 3) real array → double points, exactly.
[[nodiscard]] std::vector<glm::dvec3> pointsFromArray(py::handle array, const char* name);
/// (m, 3) integer array → triangles. Negative indices are refused always; indices ≥
/// `vertexCount` only when `checkRange` (the validation report counts them instead).
[[nodiscard]] std::vector<glm::uvec3> trianglesFromArray(py::handle array, std::size_t vertexCount, const char* name,
                                                         bool checkRange = true);
/// V and F as one mesh, every index checked.
[[nodiscard]] TriangleMesh meshFromArrays(py::handle vertices, py::handle triangles);
/// (k, n, 3) real array (or a sequence of (n, 3) arrays) → k poses of n float positions.
[[nodiscard]] std::vector<std::vector<glm::vec3>> posesFromArray(py::handle poses, const char* name);

/// Float positions as an (n, 3) float64 array (a widening copy).
[[nodiscard]] py::array_t<double> positionsArray(const std::vector<glm::vec3>& positions);
/// Double points as a (p, 3) float64 array that owns `points` (no copy).
[[nodiscard]] py::array_t<double> pointsArray(std::vector<glm::dvec3>&& points);
/// Triangles as an (m, 3) int32 array that owns `triangles` (no copy; indices < 2³¹).
[[nodiscard]] py::array_t<std::int32_t> trianglesArray(std::vector<glm::uvec3>&& triangles);
/// (V, F) of `mesh`.
[[nodiscard]] py::tuple meshArrays(TriangleMesh&& mesh);
/// Poses (float or double positions) as a (k, n, 3) float64 array.
[[nodiscard]] py::array_t<double> posesArray(const std::vector<std::vector<glm::vec3>>& poses);
[[nodiscard]] py::array_t<double> posesArray(const std::vector<std::vector<glm::dvec3>>& poses);
/// A vector of numbers as a 1-D array that owns it (no copy).
template <class T>
[[nodiscard]] py::array_t<T> vectorArray(std::vector<T>&& values);

/// A heap copy of `values` kept alive by the capsule an array holds as its base.
template <class T>
py::capsule ownerOf(std::vector<T>&& values, T*& data)
{
    auto* owned = new std::vector<T>(std::move(values));
    data = owned->data();
    return py::capsule(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
}

template <class T>
py::array_t<T> vectorArray(std::vector<T>&& values)
{
    const py::ssize_t count = py::ssize_t(values.size());
    T* data = nullptr;
    py::capsule owner = ownerOf(std::move(values), data);
    return py::array_t<T>({count}, {py::ssize_t(sizeof(T))}, data, owner);
}

} // namespace trimlab::python
