#include "render/gl/bindings.h"

namespace trimlab::render::binding {

namespace {

QString define(const char* name, GLuint value)
{
    return QStringLiteral("%1 %2").arg(QLatin1String(name)).arg(value);
}

} // namespace

QStringList glslBindingDefines()
{
    return {
        define("IMAGE_COUNTER", kCounterImage),
        define("IMAGE_SEMAPHORE", kSemaphoreImage),
        define("IMAGE_WINDING", kWindingImage),
        define("IMAGE_OVERFLOW", kOverflowImage),
        define("IMAGE_FRAGMENTS", kFragmentsImage),
        define("IMAGE_HEAD", kHeadImage),
        define("IMAGE_PEEL_DEPTH", kPeelDepthImage),
        define("IMAGE_WALK", kWalkImage),
        define("STORAGE_SCENE_COLORS", kSceneColorsStorage),
        define("STORAGE_SCENE_POSITIONS", kScenePositionsStorage),
        define("STORAGE_SCENE_NORMALS", kSceneNormalsStorage),
        define("STORAGE_SCENE_INDICES", kSceneIndicesStorage),
        define("STORAGE_SCENE_OBJECTS", kSceneObjectsStorage),
        define("STORAGE_NODES", kNodesStorage),
        define("STORAGE_LINKS", kLinksStorage),
        define("STORAGE_SHARED_COUNTERS", kSharedCountersStorage),
        define("STORAGE_DYNAMIC_STATE", kDynamicStateStorage),
        define("STORAGE_REFERENCE_BITS", kReferenceBitsStorage),
        define("STORAGE_CHARACTERIZATION_BITS", kCharacterizationBitsStorage),
        define("STORAGE_OBJECT_WINDINGS", kObjectWindingsStorage),
        define("STORAGE_SKINNING_SOURCE", kSkinningSourceStorage),
        define("STORAGE_SKINNING_INFLUENCES", kSkinningInfluencesStorage),
        define("STORAGE_SKINNING_WEIGHTS", kSkinningWeightsStorage),
        define("STORAGE_SKINNING_TRANSFORMS", kSkinningTransformsStorage),
        define("STORAGE_VERTEX_RING", kVertexRingStorage),
        define("ATOMIC_FRAME_COUNTERS", kFrameCountersAtomic),
    };
}

} // namespace trimlab::render::binding
