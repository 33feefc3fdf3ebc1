// Insertion into a pixel's k slots while holding its lock (thesis 7.1.2): the max-array
// (farthest fragment at slot 0) or the max-heap of Algorithm 7.7. The k+-buffer picks one
// for all pixels (KPLUS_HEAP); K+B-SB (KPLUS_NODE_REGION) picks per pixel as thesis 7.1.3
// says: the max-heap where the pixel overflows (f(p) > k, flagged by its referencing
// pass) and k > 16, else the max-array.
// Slot 0 is only ever written with its final value, so culling reads of slot 0 outside
// the lock never see a maximum smaller than the true one.
// Needs kplus_storage.glsl (with write access) and fragment_pack.glsl.

uniform int u_k;

#ifdef KPLUS_NODE_REGION
void storeSlot(ivec2 pixel, int slot, uvec2 f) { nodes[g_regionStart + uint(slot)] = f; }

bool usesHeap(ivec2 pixel) { return u_k > 16 && imageLoad(u_overflow, pixel).r != 0u; }
#else
void storeSlot(ivec2 pixel, int slot, uvec2 f) { imageStore(u_fragments, ivec3(pixel, slot), uvec4(f, 0u, 0u)); }

#ifdef KPLUS_HEAP
bool usesHeap(ivec2 pixel) { return true; }
#else
bool usesHeap(ivec2 pixel) { return false; }
#endif
#endif

// Up-heap with a moving hole: parents smaller than the new fragment move down.
void heapInsertEmpty(ivec2 pixel, int count, uvec2 f, float depth)
{
    int hole = count;
    while (hole > 0) {
        int parent = (hole - 1) / 2;
        uvec2 p = loadSlot(pixel, parent);
        if (fragmentDepth(p) >= depth)
            break;
        storeSlot(pixel, hole, p);
        hole = parent;
    }
    storeSlot(pixel, hole, f);
}

// The root (maximum) is evicted; down-heap with a moving hole: larger children move up.
void heapInsertFull(ivec2 pixel, uvec2 f, float depth)
{
    int hole = 0;
    while (true) {
        int child = 2 * hole + 1;
        if (child >= u_k)
            break;
        uvec2 c = loadSlot(pixel, child);
        if (child + 1 < u_k) {
            uvec2 right = loadSlot(pixel, child + 1);
            if (fragmentDepth(right) > fragmentDepth(c)) {
                c = right;
                child = child + 1;
            }
        }
        if (fragmentDepth(c) <= depth)
            break;
        storeSlot(pixel, hole, c);
        hole = child;
    }
    storeSlot(pixel, hole, f);
}
// Max-array: append; a new maximum swaps into slot 0.
void arrayInsertEmpty(ivec2 pixel, int count, uvec2 f, float depth)
{
    if (count > 0) {
        uvec2 head = loadSlot(pixel, 0);
        if (depth > fragmentDepth(head)) {
            storeSlot(pixel, count, head);
            storeSlot(pixel, 0, f);
            return;
        }
    }
    storeSlot(pixel, count, f);
}

// The maximum is evicted: the new maximum among slots 1..k-1 and f goes to slot 0.
void arrayInsertFull(ivec2 pixel, uvec2 f, float depth)
{
    int maxSlot = 0;
    float maxDepth = depth;
    for (int slot = 1; slot < u_k; ++slot) {
        float d = fragmentDepth(loadSlot(pixel, slot));
        if (d > maxDepth) {
            maxDepth = d;
            maxSlot = slot;
        }
    }
    if (maxSlot == 0) {
        storeSlot(pixel, 0, f);
    } else {
        storeSlot(pixel, 0, loadSlot(pixel, maxSlot));
        storeSlot(pixel, maxSlot, f);
    }
}

void insertEmpty(ivec2 pixel, int count, uvec2 f, float depth)
{
    if (usesHeap(pixel))
        heapInsertEmpty(pixel, count, f, depth);
    else
        arrayInsertEmpty(pixel, count, f, depth);
}

void insertFull(ivec2 pixel, uvec2 f, float depth)
{
    if (usesHeap(pixel))
        heapInsertFull(pixel, f, depth);
    else
        arrayInsertFull(pixel, f, depth);
}

// Algorithm 7.8's critical section: insert into a pixel that is not full, or replace the
// maximum of a full one (re-checking the cull under the lock).
void insertLocked(ivec2 pixel, uvec2 f, float depth)
{
    uint count = imageLoad(u_counter, pixel).r;
    if (count < uint(u_k)) {
        insertEmpty(pixel, int(count), f, depth);
        memoryBarrier(); // the slots (image or node buffer) before the count
        imageStore(u_counter, pixel, uvec4(count + 1u));
        atomicCounterIncrement(u_fragmentsStored);
        return;
    }
    imageStore(u_overflow, pixel, uvec4(1u));
    atomicCounterIncrement(u_fragmentsLost); // f or the evicted maximum
    if (depth < fragmentDepth(loadSlot(pixel, 0)))
        insertFull(pixel, f, depth);
}

// Fragment culling before taking the lock (Algorithm 7.8, line 17). Once a pixel is full
// its count stays at k and its maximum only decreases, so a stale read is safe.
bool cullBeforeLock(ivec2 pixel, float depth)
{
    if (imageLoad(u_counter, pixel).r >= uint(u_k) && depth >= fragmentDepth(loadSlot(pixel, 0))) {
        imageStore(u_overflow, pixel, uvec4(1u));
        atomicCounterIncrement(u_fragmentsLost);
        return true;
    }
    return false;
}
