// Fuzz target: the CSG expression parser behind --csg and the Inspect panel's field. Any
// text gives a tree or nullopt with an error; never a crash, a throw or a deep recursion.
// A tree that parses must print and parse back to itself, and its truth table must agree
// with evaluating it (the GPU reads the table, the CPU reference evaluates).
#include "fuzz_support.h"

#include "core/trim/csg_expression.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text = trimlab::fuzz::bytesOf(data, size);
    trimlab::fuzz::expectTypedErrors<>([&] {
        std::string error;
        const std::optional<trimlab::CsgExpression> expression = trimlab::parseCsgExpression(text, &error);
        if (!expression) {
            if (error.empty())
                std::abort(); // a refusal always says why
            return;
        }
        const std::string printed = trimlab::formatCsgExpression(*expression);
        if (trimlab::parseCsgExpression(printed, &error) != expression)
            std::abort(); // the printed form must parse back to the same tree
        const trimlab::CsgTruthTable table = trimlab::csgTruthTable(*expression);
        for (std::uint32_t mask = 0; mask < (1u << trimlab::kMaxCsgOperands); ++mask)
            if (bool((table[mask >> 5] >> (mask & 31u)) & 1u) != trimlab::evaluateCsg(*expression, mask))
                std::abort();
    });
    return 0;
}
