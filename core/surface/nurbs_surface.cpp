#include "core/surface/nurbs_surface.h"

#include "core/surface/nurbs_basis.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace trimlab {

namespace {

std::string at(const char* array, std::size_t index)
{
    return std::string(array) + "[" + std::to_string(index) + "]";
}

std::optional<NurbsProblem> findShapeProblem(const NurbsSurface& s)
{
    if (s.degreeU < 1 || s.degreeU > kMaxNurbsDegree)
        return NurbsProblem{"degreeU", "degree " + std::to_string(s.degreeU) + " is outside 1.." +
                                           std::to_string(kMaxNurbsDegree)};
    if (s.degreeV < 1 || s.degreeV > kMaxNurbsDegree)
        return NurbsProblem{"degreeV", "degree " + std::to_string(s.degreeV) + " is outside 1.." +
                                           std::to_string(kMaxNurbsDegree)};
    if (s.countU < s.degreeU + 1)
        return NurbsProblem{"countU", std::to_string(s.countU) + " control points per row are too few for degree " +
                                          std::to_string(s.degreeU) + "; use at least " +
                                          std::to_string(s.degreeU + 1)};
    if (s.countV < s.degreeV + 1)
        return NurbsProblem{"countV", std::to_string(s.countV) + " control points per column are too few for degree " +
                                          std::to_string(s.degreeV) + "; use at least " +
                                          std::to_string(s.degreeV + 1)};
    const std::size_t total = std::size_t(s.countU) * std::size_t(s.countV);
    if (total > kMaxNurbsControlPoints)
        return NurbsProblem{"countV", std::to_string(total) + " control points are more than the limit of " +
                                          std::to_string(kMaxNurbsControlPoints) + "; split the surface"};
    if (s.points.size() != total)
        return NurbsProblem{"points", std::to_string(s.points.size()) +
                                          " control points, but countU·countV = " + std::to_string(total)};
    if (s.weights.size() != total)
        return NurbsProblem{"weights", std::to_string(s.weights.size()) +
                                           " weights, but countU·countV = " + std::to_string(total)};
    return std::nullopt;
}

std::optional<NurbsProblem> findKnotProblem(const std::vector<double>& knots, int degree, int count, const char* name)
{
    const auto found = findKnotVectorProblem(knots, degree, std::size_t(count));
    if (!found)
        return std::nullopt;
    return NurbsProblem{found->index ? at(name, *found->index) : std::string(name), found->reason};
}

std::optional<NurbsProblem> findValueProblem(const NurbsSurface& s)
{
    for (std::size_t k = 0; k < s.points.size(); ++k)
        if (!std::isfinite(s.points[k].x) || !std::isfinite(s.points[k].y) || !std::isfinite(s.points[k].z))
            return NurbsProblem{at("points", k), "coordinates must be finite numbers"};
    for (std::size_t k = 0; k < s.weights.size(); ++k)
        if (!std::isfinite(s.weights[k]) || !(s.weights[k] > 0.0))
            return NurbsProblem{at("weights", k), "weights must be finite and > 0 (rational surfaces need positive "
                                                  "weights)"};
    return std::nullopt;
}

// A closed direction repeats its first row/column as its last, exactly.
std::optional<NurbsProblem> findSeamProblem(const NurbsSurface& s)
{
    if (s.closedU)
        for (int j = 0; j < s.countV; ++j) {
            const std::size_t first = s.index(0, j), last = s.index(s.countU - 1, j);
            if (s.points[first] != s.points[last] || s.weights[first] != s.weights[last])
                return NurbsProblem{at("points", last), "closedU is set, so control point (" +
                                                            std::to_string(s.countU - 1) + ", " + std::to_string(j) +
                                                            ") must equal (0, " + std::to_string(j) +
                                                            ") in position and weight; repeat the first column "
                                                            "or clear closedU"};
        }
    if (s.closedV)
        for (int i = 0; i < s.countU; ++i) {
            const std::size_t first = s.index(i, 0), last = s.index(i, s.countV - 1);
            if (s.points[first] != s.points[last] || s.weights[first] != s.weights[last])
                return NurbsProblem{at("points", last), "closedV is set, so control point (" + std::to_string(i) +
                                                            ", " + std::to_string(s.countV - 1) + ") must equal (" +
                                                            std::to_string(i) +
                                                            ", 0) in position and weight; repeat the first row or "
                                                            "clear closedV"};
        }
    return std::nullopt;
}

// Rational point and derivatives from the homogeneous sums A = Σ c (wP, w).
NurbsSample quotient(const glm::dvec4& a, const glm::dvec4& au, const glm::dvec4& av)
{
    NurbsSample sample;
    sample.position = glm::dvec3(a) / a.w;
    sample.du = (glm::dvec3(au) - au.w * sample.position) / a.w;
    sample.dv = (glm::dvec3(av) - av.w * sample.position) / a.w;
    return sample;
}

} // namespace

double nurbsDerivativeFloor(const NurbsSurface& surface)
{
    if (surface.points.empty())
        return 0.0;
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : surface.points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return 1e-10 * glm::length(hi - lo) /
           std::max(parameterRangeU(surface).length(), parameterRangeV(surface).length());
}

std::optional<glm::dvec3> regularNurbsNormal(const glm::dvec3& du, const glm::dvec3& dv, double derivativeFloor)
{
    const double lu = glm::length(du), lv = glm::length(dv);
    if (!(lu > derivativeFloor) || !(lv > derivativeFloor))
        return std::nullopt;
    const glm::dvec3 n = glm::cross(du, dv);
    const double ln = glm::length(n);
    if (!(ln > 1e-10 * lu * lv) || !std::isfinite(ln))
        return std::nullopt;
    return n / ln;
}

std::optional<NurbsProblem> findNurbsProblem(const NurbsSurface& surface)
{
    if (auto found = findShapeProblem(surface))
        return found;
    if (auto found = findKnotProblem(surface.knotsU, surface.degreeU, surface.countU, "knotsU"))
        return found;
    if (auto found = findKnotProblem(surface.knotsV, surface.degreeV, surface.countV, "knotsV"))
        return found;
    if (auto found = findValueProblem(surface))
        return found;
    return findSeamProblem(surface);
}

void requireValidNurbs(const NurbsSurface& surface, const std::string& caller)
{
    if (const auto found = findNurbsProblem(surface))
        throw std::invalid_argument(caller + ": " + found->where + ": " + found->reason);
}

ParameterRange parameterRangeU(const NurbsSurface& surface)
{
    return {surface.knotsU.front(), surface.knotsU.back()};
}

ParameterRange parameterRangeV(const NurbsSurface& surface)
{
    return {surface.knotsV.front(), surface.knotsV.back()};
}

NurbsSample evaluateNurbs(const NurbsSurface& s, double u, double v)
{
    const ParameterRange ru = parameterRangeU(s), rv = parameterRangeV(s);
    u = std::clamp(u, ru.begin, ru.end);
    v = std::clamp(v, rv.begin, rv.end);
    const std::size_t spanU = findKnotSpan(s.knotsU, s.degreeU, std::size_t(s.countU), u);
    const std::size_t spanV = findKnotSpan(s.knotsV, s.degreeV, std::size_t(s.countV), v);
    double nu[kMaxNurbsDegree + 1], du[kMaxNurbsDegree + 1], nv[kMaxNurbsDegree + 1], dv[kMaxNurbsDegree + 1];
    const std::size_t pu = std::size_t(s.degreeU) + 1, pv = std::size_t(s.degreeV) + 1;
    basisFunctionsAndDerivatives(s.knotsU, s.degreeU, spanU, u, {nu, pu}, {du, pu});
    basisFunctionsAndDerivatives(s.knotsV, s.degreeV, spanV, v, {nv, pv}, {dv, pv});
    glm::dvec4 a(0.0), au(0.0), av(0.0);
    for (std::size_t l = 0; l < pv; ++l) {
        const int j = int(spanV - pv + 1 + l);
        glm::dvec4 row(0.0), rowDu(0.0);
        for (std::size_t k = 0; k < pu; ++k) {
            const std::size_t c = s.index(int(spanU - pu + 1 + k), j);
            const glm::dvec4 h(s.points[c] * s.weights[c], s.weights[c]);
            row += nu[k] * h;
            rowDu += du[k] * h;
        }
        a += nv[l] * row;
        au += nv[l] * rowDu;
        av += dv[l] * row;
    }
    return quotient(a, au, av);
}

glm::dvec3 evaluateNurbsPoint(const NurbsSurface& surface, double u, double v)
{
    return evaluateNurbs(surface, u, v).position;
}

glm::dvec3 nurbsNormal(const NurbsSurface& s, double u, double v)
{
    const ParameterRange ru = parameterRangeU(s), rv = parameterRangeV(s);
    u = std::clamp(u, ru.begin, ru.end);
    v = std::clamp(v, rv.begin, rv.end);
    const double floor = nurbsDerivativeFloor(s);
    const auto normalAt = [&](double pu, double pv) {
        const NurbsSample sample = evaluateNurbs(s, pu, pv);
        return regularNurbsNormal(sample.du, sample.dv, floor);
    };
    if (const auto n = normalAt(u, v))
        return *n;
    // Nudge towards the middle of the domain: the limit normal from inside.
    const double towardsU = u < 0.5 * (ru.begin + ru.end) ? 1.0 : -1.0;
    const double towardsV = v < 0.5 * (rv.begin + rv.end) ? 1.0 : -1.0;
    for (const double step : {1e-6, 1e-4, 1e-2}) {
        const double nudgedV = v + towardsV * step * rv.length();
        if (const auto n = normalAt(u, nudgedV))
            return *n;
        const double nudgedU = u + towardsU * step * ru.length();
        if (const auto n = normalAt(nudgedU, v))
            return *n;
        if (const auto n = normalAt(nudgedU, nudgedV))
            return *n;
    }
    return glm::dvec3(0.0);
}

bool isPole(const NurbsSurface& s, NurbsSide side)
{
    const bool alongV = side == NurbsSide::UBegin || side == NurbsSide::UEnd; // a column
    if (alongV ? s.closedU : s.closedV)
        return false;
    const int fixed = side == NurbsSide::UBegin || side == NurbsSide::VBegin ? 0 : alongV ? s.countU - 1 : s.countV - 1;
    const int n = alongV ? s.countV : s.countU;
    const glm::dvec3 first = s.points[alongV ? s.index(fixed, 0) : s.index(0, fixed)];
    for (int k = 1; k < n; ++k)
        if (s.points[alongV ? s.index(fixed, k) : s.index(k, fixed)] != first)
            return false;
    return true;
}

namespace {

void addUnique(std::vector<std::size_t>& list, std::vector<std::size_t>& pending, std::size_t index)
{
    if (std::find(list.begin(), list.end(), index) == list.end()) {
        list.push_back(index);
        pending.push_back(index);
    }
}

// Direct ties of (i, j): seam twins and the other points of the poles it lies on.
void directTies(const NurbsSurface& s, int i, int j, std::vector<std::size_t>& list, std::vector<std::size_t>& pending)
{
    if (s.closedU && (i == 0 || i == s.countU - 1))
        addUnique(list, pending, s.index(i == 0 ? s.countU - 1 : 0, j));
    if (s.closedV && (j == 0 || j == s.countV - 1))
        addUnique(list, pending, s.index(i, j == 0 ? s.countV - 1 : 0));
    const auto pole = [&](NurbsSide side, bool onIt, bool column, int fixed) {
        if (!onIt || !isPole(s, side))
            return;
        const int n = column ? s.countV : s.countU;
        for (int k = 0; k < n; ++k)
            addUnique(list, pending, column ? s.index(fixed, k) : s.index(k, fixed));
    };
    pole(NurbsSide::UBegin, i == 0, true, 0);
    pole(NurbsSide::UEnd, i == s.countU - 1, true, s.countU - 1);
    pole(NurbsSide::VBegin, j == 0, false, 0);
    pole(NurbsSide::VEnd, j == s.countV - 1, false, s.countV - 1);
}

void collectLinked(const NurbsSurface& s, std::size_t index, std::vector<std::size_t>& out)
{
    std::vector<std::size_t> pending{index};
    out.push_back(index);
    while (!pending.empty()) {
        const std::size_t c = pending.back();
        pending.pop_back();
        directTies(s, int(c % std::size_t(s.countU)), int(c / std::size_t(s.countU)), out, pending);
    }
}

} // namespace

std::vector<std::size_t> linkedControlPoints(const NurbsSurface& surface, std::size_t index)
{
    if (index >= surface.points.size() || surface.countU <= 0)
        return {};
    std::vector<std::size_t> linked;
    collectLinked(surface, index, linked);
    std::sort(linked.begin(), linked.end());
    return linked;
}

void moveControlPoint(NurbsSurface& surface, std::size_t index, const glm::dvec3& position)
{
    if (index >= surface.points.size())
        throw std::out_of_range("moveControlPoint: control point " + std::to_string(index) +
                                " does not exist (the net has " + std::to_string(surface.points.size()) + ")");
    if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z))
        throw std::invalid_argument("moveControlPoint: the new position is not finite");
    for (const std::size_t k : linkedControlPoints(surface, index))
        surface.points[k] = position;
}

void setControlWeight(NurbsSurface& surface, std::size_t index, double weight)
{
    if (index >= surface.weights.size())
        throw std::out_of_range("setControlWeight: control point " + std::to_string(index) +
                                " does not exist (the net has " + std::to_string(surface.weights.size()) + ")");
    if (!std::isfinite(weight) || !(weight > 0.0))
        throw std::invalid_argument("setControlWeight: weights must be finite and > 0");
    // Only seam twins share weights; pole points keep theirs.
    const int i = int(index % std::size_t(surface.countU)), j = int(index / std::size_t(surface.countU));
    const bool seamU = surface.closedU && (i == 0 || i == surface.countU - 1);
    const bool seamV = surface.closedV && (j == 0 || j == surface.countV - 1);
    const int iTwin = i == 0 ? surface.countU - 1 : 0, jTwin = j == 0 ? surface.countV - 1 : 0;
    surface.weights[index] = weight;
    if (seamU)
        surface.weights[surface.index(iTwin, j)] = weight;
    if (seamV)
        surface.weights[surface.index(i, jTwin)] = weight;
    if (seamU && seamV)
        surface.weights[surface.index(iTwin, jTwin)] = weight;
}

} // namespace trimlab
