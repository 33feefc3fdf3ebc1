#include "core/trim/csg_object_ids.h"

#include "core/trim/csg_expression.h"

namespace trimlab {

std::optional<CsgObjectIdProblem> csgObjectIdOutsideScene(const CsgSettings& csg, std::size_t objectCount)
{
    if (csg.enabled()) {
        const int maxId = csgMaxObjectId(csg.expression);
        if (maxId >= int(objectCount))
            return CsgObjectIdProblem{true, maxId};
    }
    for (std::size_t id = objectCount; id < csg.objectRules.size(); ++id)
        if (csg.objectRules[id])
            return CsgObjectIdProblem{false, int(id)};
    return std::nullopt;
}

std::string csgObjectIdReason(int id, std::size_t objectCount)
{
    return "refers to object " + std::to_string(id) + ", but the scene has " + std::to_string(objectCount) +
           " object(s) (ids 0 to " + std::to_string(int(objectCount) - 1) + ")";
}

} // namespace trimlab
