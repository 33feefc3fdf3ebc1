#include "render/mfr/method_parameter_table.h"

#include <stdexcept>
#include <string>

namespace trimlab::render::method_parameters {

void validateMethodParameters(const MethodParameters& parameters)
{
    requireParameterValue(kK, parameters.k);
    requireParameterValue(kSharedCounters, parameters.sharedCounters);
    if (parameters.memoryBudgetBytes > budgetBytes(MethodParameters::kMaxMemoryBudgetMegabytes))
        throw std::invalid_argument("memory-budget must be " + parameterRangeText(kMemoryBudget) + " MB, got " +
                                    std::to_string(parameters.memoryBudgetBytes) + " bytes");
}

} // namespace trimlab::render::method_parameters
