// Sorting a pixel's linked list by view depth in place, by relinking: the fallback of
// AB_LL's resolve for lists longer than its register array (LIST_MAX). Bottom-up merge
// sort on a linked list (runs of width 1, 2, 4, ... merged pairwise; O(n log n), stable,
// no extra memory). The pixel owns its nodes, so only its links are rewritten.
// `budget` bounds the loop iterations (resolve_budget.glsl); returns false, with the list
// in an unusable state, when the sort would need more.
// Needs fragment_pack.glsl and linked_list.glsl with write access to the links.

uint nextLink(uint link) { return links[link - 1u]; }

// Whether the run head `p` goes before `q` (both valid links): the first in the walk
// order (fragment_pack.glsl), or the first of two equal ones.
bool takesFirst(uint p, uint q)
{
    return !fragmentAfter(nodes[p - 1u], nodes[q - 1u]);
}

bool mergeSortList(inout uint head, inout int budget)
{
    for (int width = 1;; width *= 2) {
        uint p = head;
        uint tail = LIST_END;
        int merges = 0;
        head = LIST_END;
        while (p != LIST_END) {
            if (--budget < 0)
                return false;
            ++merges;
            // The run at p has up to `width` nodes; the run at q follows it.
            uint q = p;
            int pSize = 0;
            while (pSize < width && q != LIST_END) {
                ++pSize;
                q = nextLink(q);
                if (--budget < 0)
                    return false;
            }
            int qSize = width;
            while (pSize > 0 || (qSize > 0 && q != LIST_END)) {
                if (--budget < 0)
                    return false;
                bool fromP = pSize > 0;
                if (fromP && qSize > 0 && q != LIST_END)
                    fromP = takesFirst(p, q);
                uint e = fromP ? p : q;
                if (fromP) {
                    p = nextLink(p);
                    --pSize;
                } else {
                    q = nextLink(q);
                    --qSize;
                }
                if (tail == LIST_END)
                    head = e;
                else
                    links[tail - 1u] = e;
                tail = e;
            }
            p = q;
        }
        if (tail != LIST_END)
            links[tail - 1u] = LIST_END;
        if (merges <= 1)
            return true;
    }
    return true;
}
