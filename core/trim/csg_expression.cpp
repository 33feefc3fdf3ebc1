#include "core/trim/csg_expression.h"

#include <algorithm>
#include <vector>
#include <cassert>
#include <cctype>

namespace trimlab {

namespace {

bool isAdditive(CsgOperation operation)
{
    return operation == CsgOperation::Union || operation == CsgOperation::Difference;
}

char operatorSymbol(CsgOperation operation)
{
    switch (operation) {
    case CsgOperation::Union:
        return '|';
    case CsgOperation::Intersection:
        return '&';
    case CsgOperation::Difference:
        return '-';
    case CsgOperation::Operand:
        break;
    }
    return '?';
}

/// Recursive descent over the grammar in the header. Positions in errors are 1-based.
class Parser {
public:
    explicit Parser(std::string_view text) : m_text(text) {}

    std::optional<CsgExpression> parseAll(std::string* error)
    {
        if (m_text.size() > kMaxCsgTextLength) {
            if (error)
                *error = "the expression is " + std::to_string(m_text.size()) + " characters long; at most " +
                         std::to_string(kMaxCsgTextLength) + " are read";
            return std::nullopt;
        }
        std::optional<CsgExpression> result = expression();
        skipSpace();
        if (result && m_position < m_text.size())
            fail("unexpected '" + std::string(1, m_text[m_position]) + "'");
        if (!m_error.empty()) {
            if (error)
                *error = m_error;
            return std::nullopt;
        }
        return result;
    }

private:
    // expression := term { ('|' | '-') term }, a chain of one operator flattened.
    std::optional<CsgExpression> expression() { return chain(true); }
    // term := factor { '&' factor }
    std::optional<CsgExpression> term() { return chain(false); }

    std::optional<CsgExpression> chain(bool additive)
    {
        std::optional<CsgExpression> first = additive ? term() : factor();
        if (!first)
            return std::nullopt;
        // The chain so far: one operation over `operands` (a single operand: no node yet).
        std::vector<CsgExpression> operands{std::move(*first)};
        CsgOperation chainOperation = CsgOperation::Operand;
        int switches = 0;
        while (true) {
            skipSpace();
            if (m_position >= m_text.size())
                break;
            const char c = m_text[m_position];
            CsgOperation operation;
            if (additive && (c == '|' || c == '-'))
                operation = c == '|' ? CsgOperation::Union : CsgOperation::Difference;
            else if (!additive && c == '&')
                operation = CsgOperation::Intersection;
            else
                break;
            ++m_position;
            std::optional<CsgExpression> right = additive ? term() : factor();
            if (!right)
                return std::nullopt;
            if (operands.size() > 1 && operation != chainOperation) {
                // Left-associative: the chain so far becomes the first operand, one level
                // deeper (counted with the parentheses around it).
                if (m_depth + ++switches > kMaxCsgDepth)
                    return fail("operators change more than " + std::to_string(kMaxCsgDepth) +
                                " times at one level; group the expression with parentheses");
                CsgExpression left = CsgExpression::combine(chainOperation, operands);
                operands = {std::move(left)};
            }
            chainOperation = operation;
            operands.push_back(std::move(*right));
        }
        if (operands.size() == 1)
            return std::move(operands.front());
        return CsgExpression::combine(chainOperation, operands);
    }

    std::optional<CsgExpression> factor()
    {
        skipSpace();
        if (m_position >= m_text.size())
            return fail("expected an object id or '(' at the end");
        const char c = m_text[m_position];
        if (c == '(') {
            if (m_depth == kMaxCsgDepth)
                return fail("parentheses nested more than " + std::to_string(kMaxCsgDepth) + " deep");
            ++m_position;
            ++m_depth;
            std::optional<CsgExpression> inner = expression();
            --m_depth;
            skipSpace();
            if (!inner)
                return std::nullopt;
            if (m_position >= m_text.size() || m_text[m_position] != ')')
                return fail("expected ')'");
            ++m_position;
            return inner;
        }
        if (!std::isdigit(static_cast<unsigned char>(c)))
            return fail("expected an object id or '(', got '" + std::string(1, c) + "'");
        long id = 0;
        const std::size_t begin = m_position;
        while (m_position < m_text.size() && std::isdigit(static_cast<unsigned char>(m_text[m_position])) && id < 1000)
            id = id * 10 + (m_text[m_position++] - '0');
        if (id >= kMaxCsgOperands) {
            m_position = begin;
            return fail("object id " + std::to_string(id) +
                        " is out of range (a CSG expression addresses objects 0 to " +
                        std::to_string(kMaxCsgOperands - 1) + ")");
        }
        return CsgExpression::operand(int(id));
    }

    void skipSpace()
    {
        while (m_position < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_position])))
            ++m_position;
    }

    std::nullopt_t fail(const std::string& message)
    {
        if (m_error.empty())
            m_error = "at character " + std::to_string(m_position + 1) + ": " + message;
        m_position = m_text.size();
        return std::nullopt;
    }

    std::string_view m_text;
    std::size_t m_position = 0;
    int m_depth = 0; ///< open parentheses around the current position
    std::string m_error;
};

// Whether operand `position` of a node with `parent` operation, rooted at `child`, needs
// parentheses to parse back into the same tree (see formatCsgExpression).
bool needsParentheses(CsgOperation parent, int position, const CsgNode& child)
{
    if (child.operation == CsgOperation::Operand)
        return false;
    if (parent == CsgOperation::Intersection)
        return true; // & binds tighter than | and -, and an unbracketed & would flatten
    if (!isAdditive(child.operation))
        return false; // an intersection inside | or -
    // The first operand continues the left-associative chain: only the same operator
    // would be flattened into this node.
    return position > 0 || child.operation == parent;
}

// Appends the subtree at `index` to `out`; returns the index after it.
std::size_t format(const std::vector<CsgNode>& nodes, std::size_t index, std::string& out)
{
    const CsgNode& node = nodes[index];
    if (node.operation == CsgOperation::Operand) {
        out += std::to_string(node.objectId);
        return index + 1;
    }
    std::size_t next = index + 1;
    for (int i = 0; i < node.operandCount; ++i) {
        if (i > 0) {
            out += ' ';
            out += operatorSymbol(node.operation);
            out += ' ';
        }
        const bool parentheses = needsParentheses(node.operation, i, nodes[next]);
        if (parentheses)
            out += '(';
        next = format(nodes, next, out);
        if (parentheses)
            out += ')';
    }
    return next;
}

// The value of the subtree at `index`; `next` receives the index after it.
bool evaluate(const std::vector<CsgNode>& nodes, std::size_t index, std::uint32_t bits, std::size_t& next)
{
    const CsgNode& node = nodes[index];
    next = index + 1;
    if (node.operation == CsgOperation::Operand)
        return node.objectId >= 0 && node.objectId < kMaxCsgOperands && ((bits >> node.objectId) & 1u) != 0;
    bool result = false;
    for (int i = 0; i < node.operandCount; ++i) {
        const bool value = evaluate(nodes, next, bits, next);
        switch (node.operation) {
        case CsgOperation::Union:
            result = result || value;
            break;
        case CsgOperation::Intersection:
            result = i == 0 ? value : result && value;
            break;
        case CsgOperation::Difference:
            result = i == 0 ? value : result && !value;
            break;
        case CsgOperation::Operand:
            break;
        }
    }
    return result;
}

// Marks the operands of the subtree at `index` (pre-order) in `mask` when `subtracted`;
// returns the index after the subtree.
std::size_t markSubtracted(const std::vector<CsgNode>& nodes, std::size_t index, bool subtracted, std::uint32_t& mask)
{
    const CsgNode& node = nodes[index++];
    if (node.operation == CsgOperation::Operand) {
        if (subtracted && node.objectId >= 0 && node.objectId < 32)
            mask |= 1u << node.objectId;
        return index;
    }
    for (int i = 0; i < node.operandCount; ++i)
        index = markSubtracted(nodes, index, subtracted || (node.operation == CsgOperation::Difference && i > 0), mask);
    return index;
}

} // namespace

CsgExpression CsgExpression::operand(int objectId)
{
    CsgExpression e;
    e.m_nodes.push_back({CsgOperation::Operand, objectId, 0});
    return e;
}

CsgExpression CsgExpression::combine(CsgOperation operation, const std::vector<CsgExpression>& operands)
{
    assert(operation != CsgOperation::Operand && operands.size() >= 2);
    CsgExpression e;
    e.m_nodes.push_back({operation, -1, int(operands.size())});
    for (const CsgExpression& operand : operands) {
        assert(!operand.empty());
        e.m_nodes.insert(e.m_nodes.end(), operand.m_nodes.begin(), operand.m_nodes.end());
    }
    return e;
}

std::optional<CsgExpression> parseCsgExpression(std::string_view text, std::string* error)
{
    return Parser(text).parseAll(error);
}

std::string formatCsgExpression(const CsgExpression& expression)
{
    std::string out;
    if (!expression.empty())
        format(expression.nodes(), 0, out);
    return out;
}

bool evaluateCsg(const CsgExpression& expression, std::uint32_t insideBits)
{
    std::size_t next = 0;
    return !expression.empty() && evaluate(expression.nodes(), 0, insideBits, next);
}

std::uint32_t csgOperandMask(const CsgExpression& expression)
{
    std::uint32_t mask = 0;
    for (const CsgNode& node : expression.nodes())
        if (node.operation == CsgOperation::Operand && node.objectId >= 0 && node.objectId < 32)
            mask |= 1u << node.objectId;
    return mask;
}

std::uint32_t csgSubtractedMask(const CsgExpression& expression)
{
    std::uint32_t mask = 0;
    if (!expression.empty())
        markSubtracted(expression.nodes(), 0, false, mask);
    return mask;
}

int csgMaxObjectId(const CsgExpression& expression)
{
    int maximum = -1;
    for (const CsgNode& node : expression.nodes())
        if (node.operation == CsgOperation::Operand)
            maximum = std::max(maximum, node.objectId);
    return maximum;
}

CsgTruthTable csgTruthTable(const CsgExpression& expression)
{
    CsgTruthTable table{};
    for (std::uint32_t mask = 0; mask < (1u << kMaxCsgOperands); ++mask)
        if (evaluateCsg(expression, mask))
            table[mask >> 5] |= 1u << (mask & 31u);
    return table;
}

} // namespace trimlab
