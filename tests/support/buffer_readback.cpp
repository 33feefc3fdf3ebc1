#include "buffer_readback.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace trimlab::test {

double largestDistance(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b)
{
    double largest = 0.0;
    for (std::size_t v = 0; v < a.size(); ++v)
        largest = std::max(largest, glm::length(glm::dvec3(a[v]) - glm::dvec3(b[v])));
    return largest;
}

double largestDistance(const std::vector<glm::vec3>& a, const std::vector<glm::dvec3>& b)
{
    double largest = 0.0;
    for (std::size_t v = 0; v < a.size(); ++v)
        largest = std::max(largest, glm::length(glm::dvec3(a[v]) - b[v]));
    return largest;
}

} // namespace trimlab::test
