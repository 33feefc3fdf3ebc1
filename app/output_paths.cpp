#include "app/output_paths.h"

#include "core/io/output_paths.h"

namespace trimlab::app {

std::optional<QString> checkOutputPaths(std::initializer_list<std::pair<const char*, QString>> outputs)
{
    std::vector<io::OutputRequest> requests;
    for (const auto& [option, path] : outputs)
        requests.push_back({option, path.toStdString()});
    if (const std::optional<std::string> error = io::checkOutputPaths(requests))
        return QString::fromStdString(*error);
    return std::nullopt;
}

} // namespace trimlab::app
