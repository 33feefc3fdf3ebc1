// Static classification rules. The C++ twin and its table-driven test are
// core/trim/static_rule.{h,cpp}: a rule arrives as shaderRuleCode(), the kind
// (StaticRule::Kind) in bits 0-3 and the threshold K of the w >= K and |w| >= K kinds
// above them.

const int RULE_PARITY = 0;
const int RULE_POSITIVE_INDEX = 1;
const int RULE_ALTERNATING_BORDER = 2;
const int RULE_NONZERO = 3;
const int RULE_NEGATIVE = 4;
const int RULE_AT_LEAST = 5;
const int RULE_ABS_AT_LEAST = 6;

bool isInterior(int rule, int w)
{
    int kind = rule & 15;
    int k = rule >> 4;
    // GLSL integers are two's complement, so w & 3 is w mod 4 also for negative w.
    if (kind == RULE_PARITY)
        return (w & 1) == 1;
    if (kind == RULE_POSITIVE_INDEX)
        return w >= 1;
    if (kind == RULE_NONZERO)
        return w != 0;
    if (kind == RULE_NEGATIVE)
        return w < 0;
    if (kind == RULE_AT_LEAST)
        return w >= k;
    if (kind == RULE_ABS_AT_LEAST)
        return abs(w) >= k;
    int r = w & 3;
    return r == 1 || r == 2;
}

bool isTrimBoundary(int rule, int wBefore, int wAfter)
{
    return isInterior(rule, wBefore) != isInterior(rule, wAfter);
}
