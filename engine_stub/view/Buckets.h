#pragma once
// The buckets ("phases" in CUBE) a view sorts its objects into, and their explicit order. Names
// and order are data: they label GL debug groups, pass timings and the stats JSON.
namespace cube {

enum class Bucket : int { Shadows = 0, DepthPrepass, Opaque, AlphaTested, Sky, Particles, Hud, Count };

struct BucketInfo {
    const char* name;
    int order;  ///< pass order key within a view; views are spaced kViewOrderStride apart
};

constexpr BucketInfo kBuckets[int(Bucket::Count)] = {
    {"shadows", 5}, {"depth_prepass", 10}, {"opaque", 20}, {"alpha_tested", 30},
    {"sky", 40},           {"particles", 50}, {"hud", 90},
};

constexpr int kViewOrderStride = 1000;
constexpr int kPresentOrder = 1000000;

inline const BucketInfo& bucketInfo(Bucket b) { return kBuckets[int(b)]; }

}  // namespace cube
