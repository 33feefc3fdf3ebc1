// Sorting a pixel's fragments in the walk order (view depth, ties by object and primitive
// id: fragment_pack.glsl) in registers (thesis 7.1.2, resolve pass):
// insertion sort for short lists, shell sort for longer ones.
// Operates on the array g_fragments[FRAGMENT_ARRAY_SIZE] that the including shader
// declares before including this file (GLSL passes arrays by value, so a global avoids
// copying k entries per call).
//
// The loops never form an index before checking it: llvmpipe evaluated the array read in
// `j >= gap && a[j - gap] > d` also for j < gap and the shell sort then lost fragments
// (caught by tests/render/tst_kplus_occupancy.cpp with k = 64).

void insertionSortFragments(int count)
{
    for (int i = 1; i < count; ++i) {
        uvec2 f = g_fragments[i];
        int j = i;
        while (j >= 1) {
            uvec2 previous = g_fragments[j - 1];
            if (!fragmentAfter(previous, f))
                break;
            g_fragments[j] = previous;
            --j;
        }
        g_fragments[j] = f;
    }
}

void shellSortFragments(int count)
{
    // Knuth's gaps 1, 4, 13, 40, ...: the largest below count / 3 first.
    int gap = 1;
    while (gap < count / 3)
        gap = 3 * gap + 1;
    for (; gap >= 1; gap /= 3) {
        for (int i = gap; i < count; ++i) {
            uvec2 f = g_fragments[i];
            int j = i;
            while (j >= gap) {
                uvec2 previous = g_fragments[j - gap];
                if (!fragmentAfter(previous, f))
                    break;
                g_fragments[j] = previous;
                j -= gap;
            }
            g_fragments[j] = f;
        }
    }
}

// The resolve pass's choice (Algorithm 7.8, RESOLVE): insertion sort up to 16 entries.
void sortFragments(int count)
{
    if (count <= 16)
        insertionSortFragments(count);
    else
        shellSortFragments(count);
}
