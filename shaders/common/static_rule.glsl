// Static classification rules (thesis 8.1.1). The C++ twin and its table-driven test are
// core/trim/static_rule.{h,cpp}; the values of the RULE_ constants match StaticRule.

const int RULE_PARITY = 0;
const int RULE_POSITIVE_INDEX = 1;
const int RULE_ALTERNATING_BORDER = 2;

bool isInterior(int rule, int w)
{
    // GLSL integers are two's complement, so w & 3 is w mod 4 also for negative w.
    if (rule == RULE_PARITY)
        return (w & 1) == 1;
    if (rule == RULE_POSITIVE_INDEX)
        return w >= 1;
    int r = w & 3;
    return r == 1 || r == 2;
}

bool isTrimBoundary(int rule, int wBefore, int wAfter)
{
    return isInterior(rule, wBefore) != isInterior(rule, wAfter);
}
