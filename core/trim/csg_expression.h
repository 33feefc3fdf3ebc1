#pragma once
/// \file
/// An n-ary CSG tree over scene objects (thesis 8.1.2, "Capping and CSG Operations",
/// Algorithm 8.14 generalised from two operands to a tree): union, intersection and
/// difference of the solids the objects bound, each object classified by its own static
/// rule (CsgSettings::objectRules). A pixel's classification is the expression evaluated
/// on the per-object inside bits; the GPU evaluates the same expression as a truth table.
///
/// Text form (CLI --csg, settings files), operands are object ids (indices into
/// Scene::objects, 0 .. kMaxCsgOperands − 1):
///
///     expression := term { ('|' | '-') term }     union, difference; left-associative
///     term       := factor { '&' factor }         intersection binds tighter
///     factor     := ID | '(' expression ')'
///
/// e.g. `0 | 1`, `0 & 1`, `0 - 1`, `0 | (1 & 2)`, `(0 | 1) - 2`. A chain of one operator
/// becomes one n-ary node: `0 | 1 | 2` is Union(0, 1, 2) and `0 - 1 - 2` is
/// Difference(0, 1, 2) = 0 − (1 ∪ 2). Whitespace is ignored. There is no complement:
/// every result is a bounded solid, so the infinite component stays outside (the
/// premise of the trim, thesis 2.1).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

/// The most objects one CSG expression (and per-object classification in general, e.g.
/// collision highlighting) can address: the GPU carries one winding index per object per
/// pixel and evaluates the expression as a truth table of 2^8 bits.
inline constexpr int kMaxCsgOperands = 8;
/// The longest text parseCsgExpression reads and the deepest tree it builds (parentheses
/// and changes of operator each add a level). Eight operands never need more than a few
/// levels; the limits keep every recursive walk of a tree (parse, format, evaluate) far
/// from the stack's end whatever a user or a file types.
inline constexpr std::size_t kMaxCsgTextLength = 4096;
inline constexpr int kMaxCsgDepth = 64;

enum class CsgOperation {
    Operand,      ///< a leaf: the solid of object `objectId`
    Union,        ///< any operand inside
    Intersection, ///< every operand inside
    Difference,   ///< the first operand inside and none of the others
};

/// One node of a tree in pre-order: a leaf (Operand, objectId) or an inner node with
/// `operandCount` >= 2 direct operands, whose subtrees follow it in order.
struct CsgNode {
    CsgOperation operation = CsgOperation::Operand;
    int objectId = -1;    ///< leaves: the object id; inner nodes: −1
    int operandCount = 0; ///< inner nodes: direct operands; leaves: 0

    friend bool operator==(const CsgNode&, const CsgNode&) = default;
};

/// An n-ary CSG tree, stored as its nodes in pre-order (a plain value: copy, compare and
/// store it freely). Default-constructed it is empty: no expression.
class CsgExpression {
public:
    CsgExpression() = default;
    /// A leaf: the solid of object `objectId`.
    [[nodiscard]] static CsgExpression operand(int objectId);
    /// An inner node over `operands` (>= 2, none empty; programmer error otherwise).
    [[nodiscard]] static CsgExpression combine(CsgOperation operation, const std::vector<CsgExpression>& operands);

    [[nodiscard]] bool empty() const { return m_nodes.empty(); }
    /// The nodes in pre-order; nodes()[0] is the root.
    [[nodiscard]] const std::vector<CsgNode>& nodes() const { return m_nodes; }
    /// The root's operation.
    [[nodiscard]] CsgOperation operation() const
    {
        return m_nodes.empty() ? CsgOperation::Operand : m_nodes[0].operation;
    }

    friend bool operator==(const CsgExpression&, const CsgExpression&) = default;

private:
    std::vector<CsgNode> m_nodes;
};

/// The 2^kMaxCsgOperands-entry truth table of an expression: bit (mask & 31) of word
/// (mask >> 5) is the classification of a point whose object o is inside iff bit o of
/// `mask` is set. The GLSL walk reads it as `uniform uint u_csgTable[8]`.
using CsgTruthTable = std::array<std::uint32_t, (1u << kMaxCsgOperands) / 32u>;

/// Parses the text form above. nullopt and a one-line `error` (with the character
/// position) on a syntax error, an empty text, an id outside 0 .. kMaxCsgOperands − 1, a
/// text longer than kMaxCsgTextLength or a tree deeper than kMaxCsgDepth.
/// The result is never empty.
[[nodiscard]] std::optional<CsgExpression> parseCsgExpression(std::string_view text, std::string* error);

/// The text form, with the fewest parentheses that parse back to the same tree
/// (parseCsgExpression(formatCsgExpression(e)) == e), e.g. "0 | (1 & 2)"; "" when empty.
[[nodiscard]] std::string formatCsgExpression(const CsgExpression& expression);

/// The classification of a point whose object o is inside iff bit o of `insideBits` is
/// set (bits of objects beyond kMaxCsgOperands are ignored). An empty expression: false.
[[nodiscard]] bool evaluateCsg(const CsgExpression& expression, std::uint32_t insideBits);

/// Bit o set iff object o is an operand somewhere in the tree.
[[nodiscard]] std::uint32_t csgOperandMask(const CsgExpression& expression);

/// Bit o set iff object o is subtracted somewhere in the tree: an operand under a
/// Difference node's second or later operand. What such an object shows of itself in the
/// result is the wall it carved (its inside, seen from the cavity), which the shading
/// tells apart from an inside seen through a cut (trim_shading.h, kCarvedWallColor).
[[nodiscard]] std::uint32_t csgSubtractedMask(const CsgExpression& expression);

/// The largest object id the tree refers to (−1 when empty).
[[nodiscard]] int csgMaxObjectId(const CsgExpression& expression);

/// evaluateCsg for every mask, as a table (see CsgTruthTable).
[[nodiscard]] CsgTruthTable csgTruthTable(const CsgExpression& expression);

} // namespace trimlab
