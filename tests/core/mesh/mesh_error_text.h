#pragma once
// The message of the MeshLoadError a load throws, for tests that compare the wording.

#include "core/mesh/mesh_load_error.h"

#include <functional>
#include <string>

namespace trimlab::test {

// What `load` throws as a MeshLoadError; "" when it throws none.
inline std::string meshLoadError(const std::function<void()>& load)
{
    try {
        load();
    } catch (const MeshLoadError& e) {
        return e.what();
    }
    return "";
}

} // namespace trimlab::test
