// Sorting a pixel's fragments in the walk order (fragment_pack.glsl) in place in the node buffer: the fallback of
// the S-buffer's resolve for lists longer than its register array (LIST_MAX). The pixel
// owns its region, so no other invocation touches these nodes. Shell sort with Knuth's
// gaps, as fragment_sort.glsl does in registers (and, like it, never forming an index
// before checking it: llvmpipe evaluates both sides of &&).
// `budget` bounds the loop iterations (see resolve_budget.glsl); returns false, with the
// region partly sorted, when the sort would need more.
// Needs fragment_pack.glsl and a writable `uvec2 nodes[]`.

bool shellSortNodes(uint start, int count, inout int budget)
{
    int gap = 1;
    while (gap < count / 3)
        gap = 3 * gap + 1;
    for (; gap >= 1; gap /= 3) {
        for (int i = gap; i < count; ++i) {
            uvec2 f = nodes[start + uint(i)];
            int j = i;
            while (j >= gap) {
                if (--budget < 0)
                    return false;
                uvec2 previous = nodes[start + uint(j - gap)];
                if (!fragmentAfter(previous, f))
                    break;
                nodes[start + uint(j)] = previous;
                j -= gap;
            }
            nodes[start + uint(j)] = f;
            if (--budget < 0)
                return false;
        }
    }
    return true;
}
