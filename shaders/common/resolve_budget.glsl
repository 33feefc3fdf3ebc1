// The loop budget of a resolve's fallback for long lists. Mesa's llvmpipe ends every
// loop of a shader invocation silently once the invocation has run 65535 loop iterations
// in total (LP_MAX_TGSI_LOOP_ITERATIONS, shared by all loops), which would leave a long
// list half sorted and the pixel silently wrong. The renderer sets u_loopBudget below
// that limit on llvmpipe (render/mfr/resolve_budget.h) and to the int maximum elsewhere;
// a fallback that would exceed it stops and its pixel is reported unresolved instead.

uniform int u_loopBudget;
