// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/interface_band.h"

#include "isovdb/volume/grids.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <mutex>
#include <vector>

namespace isovdb::volume {

namespace {

using MaskLeaf = MaskGrid::TreeType::LeafNodeType;
using openvdb::Coord;
using openvdb::CoordBBox;

constexpr int kLeaf = 8;
/// The mask is blurred by a Gaussian of this many voxels, truncated at kBlurRadius.
/// 0.9 voxel: smaller leaves the staircase, larger rounds curved surfaces inwards
/// by about sigma^2 / R (bench/field_accuracy.py chose it).
constexpr float kBlurSigma = 0.9f;
constexpr int kBlurRadius = 2;
/// An interface voxel's distance needs the blurred mask at its six neighbours.
constexpr int kSiteStencil = kBlurRadius + 1;
/// The smallest |value| at an interface voxel. A voxel centre can lie on the
/// surface, but a zero would put vertices exactly on samples, and a feature
/// whose blurred value has the wrong sign would get no thickness at all (0.1:
/// the frog skeleton's regular mesh folds less than with 0.05, and analytic
/// solids lose nothing; 0.2 costs them accuracy).
constexpr float kSiteFloor = 0.1f;
/// The smallest |value| at a voxel whose six neighbours are all on its side: a
/// plane crossing none of the six unit segments around a point is at least
/// 1/sqrt(3) from it.
constexpr float kInteriorFloor = 0.5f;
constexpr std::int8_t kNoSite = std::numeric_limits<std::int8_t>::max();
/// Largest reach r = halfWidth + 1 (checkDistanceFieldOptions allows half-widths up to 64).
constexpr int kMaxReach = 65;
constexpr int kMaxSlotReach = (kMaxReach + kLeaf - 1) / kLeaf;
/// Slots along z whose site bits fit one 64-bit word in pass 1's bit scan.
constexpr int kMaxWindowSlots = 64 / kLeaf;

int roundUpToLeaf(int v) { return (v + kLeaf - 1) / kLeaf * kLeaf; }

int floorDiv(int v, int step) { return v >= 0 ? v / step : -((-v + step - 1) / step); }

/// The fixed sizes of every chunk.
struct Layout {
  Layout(int halfWidth, int chunkSize)
      : halfWidth(halfWidth),
        chunk(chunkSize),
        reach(halfWidth + 1),
        slotReach((halfWidth + 1 + kLeaf - 1) / kLeaf),
        apron(roundUpToLeaf(halfWidth + 1 + kSiteStencil)),
        n(chunkSize + 2 * apron),
        slots(n / kLeaf),
        ringSlots(slots + 2) {}

  int halfWidth;
  int chunk;      ///< C: voxels per axis of the chunk's own cube
  int reach;      ///< r: the nearest interface voxel is looked for within r per axis
  int slotReach;  ///< ceil(r / 8)
  int apron;      ///< A: mask read around the chunk (r + the site stencil, whole leaves)
  int n;          ///< N = C + 2A voxels per axis of the region
  int slots;      ///< M = N / 8 leaf-sized slots per axis
  int ringSlots;  ///< M + 2: slot records also cover one ring outside the region

  std::size_t voxel(int x, int y, int z) const {  // z fastest, like a leaf's own order
    return (static_cast<std::size_t>(x) * n + static_cast<std::size_t>(y)) * n + static_cast<std::size_t>(z);
  }
  /// Slot (sx, sy, sz) with each coordinate in -1..M.
  std::size_t slot(int sx, int sy, int sz) const {
    return (static_cast<std::size_t>(sx + 1) * ringSlots + static_cast<std::size_t>(sy + 1)) * ringSlots +
           static_cast<std::size_t>(sz + 1);
  }
  int firstInnerSlot() const { return apron / kLeaf; }
  int endInnerSlot() const { return (apron + chunk) / kLeaf; }
};

/// A slot's 512 voxels as bits, in a leaf's own order: word x, byte y, bit z.
using VoxelBits = std::array<std::uint64_t, kLeaf>;
/// A slot's 64 rows along z as bits: bit 8 x + y.
using RowBits = std::uint64_t;

RowBits rowsOf(const VoxelBits& bits) {
  RowBits rows = 0;
  for (int i = 0; i < kLeaf; ++i)
    for (int j = 0; j < kLeaf; ++j)
      if ((bits[static_cast<std::size_t>(i)] >> (8 * j)) & 0xffu) rows |= RowBits{1} << (8 * i + j);
  return rows;
}

constexpr std::uint64_t kByteLow = 0x0101010101010101ull, kByteHigh = 0x8080808080808080ull;

/// Voxel bits dilated by one voxel along one axis, given the neighbouring slots below and above.
VoxelBits dilateVoxels(const VoxelBits& w, const VoxelBits& below, const VoxelBits& above, int axis) {
  VoxelBits out{};
  for (int i = 0; i < kLeaf; ++i) {
    const std::uint64_t v = w[static_cast<std::size_t>(i)];
    const std::size_t at = static_cast<std::size_t>(i);
    switch (axis) {
      case 0:
        out[at] = v | (i > 0 ? w[at - 1] : below[kLeaf - 1]) | (i < kLeaf - 1 ? w[at + 1] : above[0]);
        break;
      case 1:
        out[at] = v | (v << 8) | (v >> 8) | (below[at] >> 56) | (above[at] << 56);
        break;
      default:
        out[at] = v | ((v << 1) & ~kByteLow) | ((v >> 1) & ~kByteHigh) | ((below[at] >> 7) & kByteLow) |
                  ((above[at] << 7) & kByteHigh);
    }
  }
  return out;
}

/// Row bits dilated by one row along x (axis 0) or y (axis 1).
RowBits dilateRows(RowBits v, RowBits below, RowBits above, int axis) {
  if (axis == 0) return v | (v << 8) | (v >> 8) | (below >> 56) | (above << 56);
  return v | ((v << 1) & ~kByteLow) | ((v >> 1) & ~kByteHigh) | ((below >> 7) & kByteLow) | ((above << 7) & kByteHigh);
}

enum SlotState : std::uint8_t { kEmpty = 0, kFull = 1, kMixed = 2 };
enum SlotFlag : std::uint8_t {
  kSites = 1,  ///< holds interface voxels within r of the chunk (their values computed)
  kBand = 2,   ///< inner slot with a voxel within r (per axis) of a site: its leaf is computed
  kPass1 = 4,  ///< has rows for pass 1 (rows1)
  kPass2 = 8,  ///< has rows for pass 2 (rows2)
};

/// Nearest site in the yz-plane of a voxel: offsets along z and y, squared distance.
struct PlaneNearest {
  std::int8_t dz, dy;
  std::uint16_t d2;
};
constexpr std::uint16_t kFar = std::numeric_limits<std::uint16_t>::max();
/// Pass 2 handles a row's eight voxels along z at once: their nearZ bytes, widened to
/// 16-bit lanes of one SSE2 register (GCC's and Clang's vector extension). Squared
/// distances stay below 127^2 + kMaxReach^2 < 2^15 (127: kNoSite); kFarLane stands for kFar.
using RowBytes = std::int8_t __attribute__((vector_size(kLeaf)));
using RowLanes = std::int16_t __attribute__((vector_size(2 * kLeaf)));
constexpr std::int16_t kFarLane = std::numeric_limits<std::int16_t>::max();
constexpr RowLanes kFarLanes = {kFarLane, kFarLane, kFarLane, kFarLane, kFarLane, kFarLane, kFarLane, kFarLane};

/// A site's signed distance to the surface and the surface's outward unit normal:
/// the tangent plane that gives the values of the voxels nearest to it. One
/// 16-byte record, so pass 3 reads it with one cache line.
struct SitePlane {
  float distance;
  std::array<float, 3> normal;
};

/// Per slot (8^3 voxels, the size of a leaf) of the region plus one ring.
struct Slot {
  std::uint8_t state = kEmpty;
  std::uint8_t flags = 0;
  const MaskLeaf* leaf = nullptr;       ///< kMixed: the mask leaf
  VoxelBits siteBits{};                 ///< its sites
  VoxelBits nearBits{};                 ///< band voxels within r (per axis) of a site: pass 3
  std::array<std::int8_t, 3> siteLo{};  ///< kSites: bounding box of the sites (slot voxels)
  std::array<std::int8_t, 3> siteHi{};
  RowBits rows2 = 0, rows1 = 0;  ///< rows of pass 2 (near dilated along x) and pass 1 (then along y)
  std::uint32_t planes = 0;      ///< kSites: its block of 512 site planes in Scratch::planes

  /// The mask's row (i, j) along z as eight bits (bit k: voxel k, 1 inside), read from
  /// the slot's state or its leaf: word i of a leaf's mask is its x = i layer, byte j of
  /// it the row y = j.
  std::uint32_t rowByte(int i, int j) const {
    if (state != kMixed) return state == kFull ? 0xffu : 0u;
    return static_cast<std::uint32_t>(leaf->getValueMask().getWord<std::uint64_t>(static_cast<openvdb::Index>(i)) >>
                                      (8 * j)) &
           0xffu;
  }
};

/// One thread's buffers, reused from chunk to chunk. Region arrays are written
/// only where a slot's flags or rows say so, and read only there.
struct Scratch {
  explicit Scratch(const Layout& layout) {
    const std::size_t voxels = static_cast<std::size_t>(layout.n) * layout.n * layout.n;
    planes.reserve(64 * static_cast<std::size_t>(kLeaf * kLeaf * kLeaf));
    nearZ.resize(voxels);
    nearYZ.resize(voxels);
    const std::size_t slotCount = static_cast<std::size_t>(layout.ringSlots) * layout.ringSlots * layout.ringSlots;
    slots.resize(slotCount);
    voxelBits.resize(slotCount);
    grownInside.resize(slotCount);
    grownOutside.resize(slotCount);
    grown.resize(slotCount);
    rowBits.resize(slotCount);
  }
  /// Sites' tangent planes, one block of 512 per site slot (in a leaf's voxel order):
  /// only slots with an interface take this memory.
  std::vector<SitePlane> planes;
  std::vector<std::int8_t> nearZ;    ///< offset along z to the nearest site (kNoSite)
  std::vector<PlaneNearest> nearYZ;  ///< nearest site in the yz-plane
  std::vector<Slot> slots;
  std::vector<VoxelBits> voxelBits;                         ///< dilation buffer
  std::vector<VoxelBits> grownInside, grownOutside, grown;  ///< the face band's dilations
  std::vector<RowBits> rowBits;                             ///< dilation buffer
  // Per site slot: the mask around it and its blur, window of 8 + 2 * kSiteStencil.
  static constexpr int kW = kLeaf + 2 * kSiteStencil;  // 14
  static constexpr int kS = kLeaf + 2;                 // 10: blurred values at the slot +-1
  std::array<std::uint32_t, kW * kW> rows{};
  std::array<float, kW * kW * kS> blurZ{};
  std::array<float, kW * kS * kS> blurYZ{};
  std::array<float, kS * kS * kS> blurred{};
};

/// Gaussian weights w[-R..R], normalised.
std::array<float, 2 * kBlurRadius + 1> blurWeights() {
  std::array<float, 2 * kBlurRadius + 1> w{};
  float sum = 0.f;
  for (int k = -kBlurRadius; k <= kBlurRadius; ++k) {
    w[k + kBlurRadius] = std::exp(-0.5f * static_cast<float>(k * k) / (kBlurSigma * kBlurSigma));
    sum += w[k + kBlurRadius];
  }
  for (float& v : w) v /= sum;
  return w;
}

/// The voxels of a mask leaf on one of its faces, as 64 bits (in some order):
/// axis 0..2, side 0 (low) or 1 (high). A leaf's bit n is voxel (n >> 6, (n >> 3) & 7, n & 7).
std::uint64_t faceBits(const MaskLeaf& leaf, int axis, int side) {
  const auto& mask = leaf.getValueMask();
  const int layer = side ? kLeaf - 1 : 0;
  if (axis == 0) return mask.getWord<std::uint64_t>(static_cast<openvdb::Index>(layer));
  std::uint64_t bits = 0;
  for (int i = 0; i < kLeaf; ++i) {
    const std::uint64_t word = mask.getWord<std::uint64_t>(static_cast<openvdb::Index>(i));
    if (axis == 1)
      bits |= ((word >> (8 * layer)) & 0xffull) << (8 * i);
    else
      bits |= ((word >> layer) & kByteLow) << i;
  }
  return bits;
}

/// Pass 1's answer from the distances to the nearest site below and above a voxel along
/// z: the offset to the nearer one within r (the lower one on a tie), or kNoSite.
std::int8_t nearerOffset(int down, int up, int r) {
  if (down <= r && down <= up) return static_cast<std::int8_t>(-down);
  if (up <= r) return static_cast<std::int8_t>(up);
  return kNoSite;
}

/// Computes one chunk: slot states from the mask tree, the sites and their values,
/// the voxels within reach of them (bit masks, dilated the way the passes read),
/// the three passes of the nearest-site transform on those rows, and the leaves.
class ChunkBand {
 public:
  ChunkBand(const MaskGrid& mask, const Layout& layout) : mask_(mask), layout_(layout) {
    // The blur along z of every pattern of 2R + 1 mask bits (bit t: the voxel at
    // offset t - R; -1 inside, +1 outside), so the first pass reads one table entry.
    const std::array<float, 2 * kBlurRadius + 1> weights = blurWeights();
    for (std::uint32_t pattern = 0; pattern < rowBlur_.size(); ++pattern) {
      float sum = 0.f;
      for (int t = 0; t <= 2 * kBlurRadius; ++t)
        sum += weights[static_cast<std::size_t>(t)] * (((pattern >> t) & 1u) ? -1.f : 1.f);
      rowBlur_[pattern] = sum;
    }
    weights_ = weights;
  }

  /// The band's leaves of the chunk whose cube starts at `chunkOrigin`.
  void compute(const Coord& chunkOrigin, Scratch& s, std::vector<std::unique_ptr<FieldLeaf>>& out) const {
    const Coord regionMin = chunkOrigin.offsetBy(-layout_.apron);
    readSlotStates(regionMin, s);
    s.planes.clear();
    if (!markSiteSlots(s)) return;
    bool anySite = false;
    forEachSlot(s, kSites, [&](int sx, int sy, int sz) { anySite = computeSites(sx, sy, sz, s) || anySite; });
    if (!anySite || !markBand(s)) return;
    forEachSlot(s, kPass1, [&](int sx, int sy, int sz) { nearestAlongZ(sx, sy, sz, s); });
    forEachSlot(s, kPass2, [&](int sx, int sy, int sz) { nearestInPlane(sx, sy, sz, s); });
    forEachSlot(s, kBand, [&](int sx, int sy, int sz) {
      if (auto leaf = bandLeaf(regionMin, sx, sy, sz, s)) out.push_back(std::move(leaf));
    });
  }

 private:
  Slot& slot(Scratch& s, int sx, int sy, int sz) const { return s.slots[layout_.slot(sx, sy, sz)]; }

  template <typename F>
  void forEachSlot(Scratch& s, std::uint8_t flag, F&& f) const {
    const int m = layout_.slots;
    for (int sx = 0; sx < m; ++sx)
      for (int sy = 0; sy < m; ++sy)
        for (int sz = 0; sz < m; ++sz)
          if (slot(s, sx, sy, sz).flags & flag) f(sx, sy, sz);
  }

  void readSlotStates(const Coord& regionMin, Scratch& s) const {
    auto acc = mask_.getConstAccessor();
    const int m = layout_.slots;
    for (int sx = -1; sx <= m; ++sx)
      for (int sy = -1; sy <= m; ++sy)
        for (int sz = -1; sz <= m; ++sz) {
          Slot& at = slot(s, sx, sy, sz);
          at = Slot{};
          const Coord origin = regionMin.offsetBy(sx * kLeaf, sy * kLeaf, sz * kLeaf);
          if (const MaskLeaf* leaf = acc.probeConstLeaf(origin)) {
            if (leaf->isValueMaskOn()) {
              at.state = kFull;
            } else if (!leaf->isValueMaskOff()) {
              at.state = kMixed;
              at.leaf = leaf;
            }
          } else if (acc.isValueOn(origin)) {
            at.state = kFull;
          }
        }
  }

  /// True when a uniform slot has a voxel of the other side across its face
  /// towards the neighbour at `axis` and `side` (0: below, 1: above).
  bool faceDiffers(const Slot& uniform, const Slot& neighbour, int axis, int side) const {
    if (neighbour.state != kMixed) return neighbour.state != uniform.state;
    const std::uint64_t bits = faceBits(*neighbour.leaf, axis, 1 - side);
    return uniform.state == kFull ? bits != ~0ull : bits != 0;
  }

  /// kSites on the slots within reach of the chunk that hold interface voxels.
  bool markSiteSlots(Scratch& s) const {
    const int reach = layout_.slotReach;
    const int begin = layout_.firstInnerSlot() - reach, end = layout_.endInnerSlot() + reach;
    bool any = false;
    for (int sx = begin; sx < end; ++sx)
      for (int sy = begin; sy < end; ++sy)
        for (int sz = begin; sz < end; ++sz) {
          Slot& at = slot(s, sx, sy, sz);
          bool border = at.state == kMixed;
          for (int axis = 0; axis < 3 && !border; ++axis)
            for (int side = 0; side < 2 && !border; ++side) {
              const int d = side ? 1 : -1;
              border = faceDiffers(at, slot(s, sx + (axis == 0) * d, sy + (axis == 1) * d, sz + (axis == 2) * d), axis,
                                   side);
            }
          if (!border) continue;
          at.flags |= kSites;
          any = true;
        }
    return any;
  }

  bool computeSites(int sx, int sy, int sz, Scratch& s) const {
    constexpr int W = Scratch::kW, S = Scratch::kS, St = kSiteStencil;
    static_assert(St <= kLeaf && kLeaf + 2 * St <= 32);
    const int m = layout_.slots;
    // The mask around the slot as one 14-bit row along z per (x, y), from the rows of the
    // slot and its neighbours below and above: bit k is window voxel k, 1 inside (outside
    // the region: 0, never used for a site).
    static const Slot kOutside{};
    auto slotOrOutside = [&](int x, int y, int z) -> const Slot& {
      return x >= 0 && y >= 0 && z >= 0 && x < m && y < m && z < m ? slot(s, x, y, z) : kOutside;
    };
    for (int i = 0; i < W; ++i)
      for (int j = 0; j < W; ++j) {
        // Window (i, j) is voxel (i - St, j - St) of the slot: slot offset and voxel in it.
        const int ox = i < St ? -1 : i >= St + kLeaf ? 1 : 0, oy = j < St ? -1 : j >= St + kLeaf ? 1 : 0;
        const int vi = i - St - kLeaf * ox, vj = j - St - kLeaf * oy;
        const int x = sx + ox, y = sy + oy;
        const std::uint32_t below = slotOrOutside(x, y, sz - 1).rowByte(vi, vj);
        const std::uint32_t here = slotOrOutside(x, y, sz).rowByte(vi, vj);
        const std::uint32_t above = slotOrOutside(x, y, sz + 1).rowByte(vi, vj);
        s.rows[static_cast<std::size_t>(i * W + j)] =
            (below >> (kLeaf - St)) | (here << St) | ((above & ((1u << St) - 1)) << (St + kLeaf));
      }
    auto rowAt = [&s](int i, int j) { return s.rows[static_cast<std::size_t>((i + St) * W + j + St)]; };
    // The slot's interface voxels within r of the chunk: a voxel whose row, or the row
    // beside it in x or y, differs at its bit or a z neighbour's.
    Slot& at = slot(s, sx, sy, sz);
    const int lo = layout_.apron - layout_.reach, hi = layout_.apron + layout_.chunk + layout_.reach;
    at.siteBits = {};
    at.siteLo = {kLeaf, kLeaf, kLeaf};
    at.siteHi = {-1, -1, -1};
    for (int i = 0; i < kLeaf; ++i)
      for (int j = 0; j < kLeaf; ++j) {
        const int x = sx * kLeaf + i, y = sy * kLeaf + j;
        if (x < lo || y < lo || x >= hi || y >= hi) continue;
        const std::uint32_t c = rowAt(i, j);
        const std::uint32_t differs = (c ^ (c << 1)) | (c ^ (c >> 1)) | (c ^ rowAt(i - 1, j)) | (c ^ rowAt(i + 1, j)) |
                                      (c ^ rowAt(i, j - 1)) | (c ^ rowAt(i, j + 1));
        std::uint32_t inner = (differs >> St) & 0xffu;  // bit k: slot voxel k
        for (int k = 0; k < kLeaf; ++k) {
          const int z = sz * kLeaf + k;
          if (z < lo || z >= hi) inner &= ~(1u << k);
        }
        if (!inner) continue;
        at.siteBits[static_cast<std::size_t>(i)] |= static_cast<std::uint64_t>(inner) << (8 * j);
        at.siteLo[0] = static_cast<std::int8_t>(std::min<int>(at.siteLo[0], i));
        at.siteHi[0] = static_cast<std::int8_t>(std::max<int>(at.siteHi[0], i));
        at.siteLo[1] = static_cast<std::int8_t>(std::min<int>(at.siteLo[1], j));
        at.siteHi[1] = static_cast<std::int8_t>(std::max<int>(at.siteHi[1], j));
        at.siteLo[2] = static_cast<std::int8_t>(std::min<int>(at.siteLo[2], std::countr_zero(inner)));
        at.siteHi[2] = static_cast<std::int8_t>(std::max<int>(at.siteHi[2], 31 - std::countl_zero(inner)));
      }
    if (at.siteHi[0] < 0) {
      at.flags &= static_cast<std::uint8_t>(~kSites);
      return false;
    }
    at.planes = static_cast<std::uint32_t>(s.planes.size());
    s.planes.resize(s.planes.size() + kLeaf * kLeaf * kLeaf);
    SitePlane* planes = &s.planes[at.planes];
    // Separable blur over the sites' bounding box and one voxel around it
    // (blurred index b <-> slot voxel b - 1 <-> window index b + kOff).
    constexpr int R = kBlurRadius, kOff = St - 1;
    const int bLo[3] = {at.siteLo[0], at.siteLo[1], at.siteLo[2]};  // slot voxel lo - 1, + 1
    const int bHi[3] = {at.siteHi[0] + 3, at.siteHi[1] + 3, at.siteHi[2] + 3};
    const int wLo[3] = {bLo[0] + kOff - R, bLo[1] + kOff - R, bLo[2] + kOff - R};
    const int wHi[3] = {bHi[0] + kOff + R, bHi[1] + kOff + R, bHi[2] + kOff + R};
    for (int i = wLo[0]; i < wHi[0]; ++i)
      for (int j = wLo[1]; j < wHi[1]; ++j) {
        const std::uint32_t row = s.rows[static_cast<std::size_t>(i * W + j)];
        for (int k = bLo[2]; k < bHi[2]; ++k)  // window voxels k + kOff - R .. k + kOff + R
          s.blurZ[(i * W + j) * S + k] = rowBlur_[(row >> (k + kOff - R)) & ((1u << (2 * R + 1)) - 1)];
      }
    for (int i = wLo[0]; i < wHi[0]; ++i)
      for (int j = bLo[1]; j < bHi[1]; ++j)
        for (int k = bLo[2]; k < bHi[2]; ++k) {
          float sum = 0.f;
          for (int t = -R; t <= R; ++t) sum += weights_[t + R] * s.blurZ[(i * W + j + kOff + t) * S + k];
          s.blurYZ[(i * S + j) * S + k] = sum;
        }
    for (int i = bLo[0]; i < bHi[0]; ++i)
      for (int j = bLo[1]; j < bHi[1]; ++j)
        for (int k = bLo[2]; k < bHi[2]; ++k) {
          float sum = 0.f;
          for (int t = -R; t <= R; ++t) sum += weights_[t + R] * s.blurYZ[((i + kOff + t) * S + j) * S + k];
          s.blurred[(i * S + j) * S + k] = sum;
        }
    auto blurredAt = [&s](int i, int j, int k) { return s.blurred[((i + 1) * S + j + 1) * S + k + 1]; };
    auto maskAt = [&rowAt](int i, int j, int k) { return ((rowAt(i, j) >> (k + St)) & 1u) != 0; };
    for (int i = at.siteLo[0]; i <= at.siteHi[0]; ++i)
      for (int j = at.siteLo[1]; j <= at.siteHi[1]; ++j)
        for (int k = at.siteLo[2]; k <= at.siteHi[2]; ++k) {
          if (!((at.siteBits[static_cast<std::size_t>(i)] >> (8 * j + k)) & 1u)) continue;
          const bool inside = maskAt(i, j, k);
          const float here = blurredAt(i, j, k);
          const float gx = 0.5f * (blurredAt(i + 1, j, k) - blurredAt(i - 1, j, k));
          const float gy = 0.5f * (blurredAt(i, j + 1, k) - blurredAt(i, j - 1, k));
          const float gz = 0.5f * (blurredAt(i, j, k + 1) - blurredAt(i, j, k - 1));
          const float length = std::sqrt(gx * gx + gy * gy + gz * gz);
          std::array<float, 3> normal{0.f, 0.f, 0.f};
          if (length > 1e-4f) normal = {gx / length, gy / length, gz / length};
          // Where the blurred mask crosses zero on each edge to a neighbour of the other
          // side (linear interpolation, as the contouring reads the field), projected on
          // the normal: each crossing is a point of the tangent plane, and edges along the
          // normal say most about its distance (weights n_a^2). A plane's distance comes
          // out exact, an axis-aligned face's 0.5 included.
          float sum = 0.f, weights = 0.f;
          const int step[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
          for (int e = 0; e < 6; ++e) {
            const int a = e / 2;
            const int ni = i + step[e][0], nj = j + step[e][1], nk = k + step[e][2];
            if (maskAt(ni, nj, nk) == inside) continue;
            const float there = blurredAt(ni, nj, nk);
            const float t = std::clamp(here / (here - there + (here == there ? 1e-6f : 0.f)), 0.02f, 0.98f);
            const float w = normal[static_cast<std::size_t>(a)] * normal[static_cast<std::size_t>(a)];
            sum += w * t * std::abs(normal[static_cast<std::size_t>(a)]);
            weights += w;
          }
          float d = weights > 1e-6f ? (inside ? -1.f : 1.f) * sum / weights : (inside ? -0.5f : 0.5f);
          // A voxel with the other side on both faces along an axis is a feature one voxel
          // thick: its blur cannot place either surface, and the mask puts them half a
          // voxel away.
          for (int a = 0; a < 3; ++a) {
            const int di = a == 0, dj = a == 1, dk = a == 2;
            if (maskAt(i - di, j - dj, k - dk) != inside && maskAt(i + di, j + dj, k + dk) != inside)
              d = inside ? std::min(d, -0.5f) : std::max(d, 0.5f);
          }
          // The mask decides the side; the surface is within one voxel of an interface voxel.
          planes[(i << 6) | (j << 3) | k] = {inside ? std::clamp(d, -1.f, -kSiteFloor) : std::clamp(d, kSiteFloor, 1.f),
                                             normal};
        }
    return true;
  }

  /// Sets `target` = `source` dilated by r voxels along `axis`, on every slot of
  /// the region (the ring stays empty).
  void dilateVoxelBits(Scratch& s, VoxelBits Slot::*source, VoxelBits Slot::*target, int axis) const {
    const int m = layout_.slots;
    for (int sx = 0; sx < m; ++sx)
      for (int sy = 0; sy < m; ++sy)
        for (int sz = 0; sz < m; ++sz) s.voxelBits[layout_.slot(sx, sy, sz)] = slot(s, sx, sy, sz).*source;
    const int d[3] = {axis == 0, axis == 1, axis == 2};
    for (int step = 0; step < layout_.reach; ++step) {
      for (int sx = 0; sx < m; ++sx)
        for (int sy = 0; sy < m; ++sy)
          for (int sz = 0; sz < m; ++sz) {
            auto bitsAt = [&](int x, int y, int z) -> VoxelBits {
              if (x < 0 || y < 0 || z < 0 || x >= m || y >= m || z >= m) return {};
              return s.voxelBits[layout_.slot(x, y, z)];
            };
            slot(s, sx, sy, sz).*target =
                dilateVoxels(s.voxelBits[layout_.slot(sx, sy, sz)], bitsAt(sx - d[0], sy - d[1], sz - d[2]),
                             bitsAt(sx + d[0], sy + d[1], sz + d[2]), axis);
          }
      for (int sx = 0; sx < m; ++sx)
        for (int sy = 0; sy < m; ++sy)
          for (int sz = 0; sz < m; ++sz) s.voxelBits[layout_.slot(sx, sy, sz)] = slot(s, sx, sy, sz).*target;
    }
  }

  /// Sets `target` = `source` dilated by r rows along x (axis 0) or y (axis 1).
  void dilateRowBits(Scratch& s, RowBits Slot::*source, RowBits Slot::*target, int axis) const {
    const int m = layout_.slots;
    for (int sx = 0; sx < m; ++sx)
      for (int sy = 0; sy < m; ++sy)
        for (int sz = 0; sz < m; ++sz) s.rowBits[layout_.slot(sx, sy, sz)] = slot(s, sx, sy, sz).*source;
    const int dx = axis == 0, dy = axis == 1;
    for (int step = 0; step < layout_.reach; ++step) {
      for (int sx = 0; sx < m; ++sx)
        for (int sy = 0; sy < m; ++sy)
          for (int sz = 0; sz < m; ++sz) {
            auto rowsAt = [&](int x, int y) -> RowBits {
              if (x < 0 || y < 0 || x >= m || y >= m) return 0;
              return s.rowBits[layout_.slot(x, y, sz)];
            };
            slot(s, sx, sy, sz).*target = dilateRows(s.rowBits[layout_.slot(sx, sy, sz)], rowsAt(sx - dx, sy - dy),
                                                     rowsAt(sx + dx, sy + dy), axis);
          }
      for (int sx = 0; sx < m; ++sx)
        for (int sy = 0; sy < m; ++sy)
          for (int sz = 0; sz < m; ++sz) s.rowBits[layout_.slot(sx, sy, sz)] = slot(s, sx, sy, sz).*target;
    }
  }

  /// A slot's inside voxels as bits.
  static VoxelBits insideBits(const Slot& at) {
    VoxelBits bits{};
    if (at.state == kFull) bits.fill(~std::uint64_t{0});
    if (at.leaf)
      for (std::size_t w = 0; w < kLeaf; ++w)
        bits[w] = at.leaf->getValueMask().getWord<std::uint64_t>(static_cast<openvdb::Index>(w));
    return bits;
  }

  /// grownInside / grownOutside: the inside and the outside voxels grown by halfWidth
  /// face-neighbour steps (what tools::dilateActiveValues with NN_FACE does).
  void growFaceSteps(Scratch& s) const {
    const int m = layout_.slots;
    auto bitsAt = [&](const std::vector<VoxelBits>& from, int x, int y, int z) -> VoxelBits {
      if (x < 0 || y < 0 || z < 0 || x >= m || y >= m || z >= m) return {};
      return from[layout_.slot(x, y, z)];
    };
    for (int sx = 0; sx < m; ++sx)
      for (int sy = 0; sy < m; ++sy)
        for (int sz = 0; sz < m; ++sz) {
          const std::size_t at = layout_.slot(sx, sy, sz);
          s.grownInside[at] = insideBits(s.slots[at]);
          for (std::size_t w = 0; w < kLeaf; ++w) s.grownOutside[at][w] = ~s.grownInside[at][w];
        }
    for (std::vector<VoxelBits>* grown : {&s.grownInside, &s.grownOutside})
      for (int step = 0; step < layout_.halfWidth; ++step) {
        for (int sx = 0; sx < m; ++sx)
          for (int sy = 0; sy < m; ++sy)
            for (int sz = 0; sz < m; ++sz) {
              const VoxelBits& here = (*grown)[layout_.slot(sx, sy, sz)];
              VoxelBits out = dilateVoxels(here, bitsAt(*grown, sx - 1, sy, sz), bitsAt(*grown, sx + 1, sy, sz), 0);
              const VoxelBits alongY =
                  dilateVoxels(here, bitsAt(*grown, sx, sy - 1, sz), bitsAt(*grown, sx, sy + 1, sz), 1);
              const VoxelBits alongZ =
                  dilateVoxels(here, bitsAt(*grown, sx, sy, sz - 1), bitsAt(*grown, sx, sy, sz + 1), 2);
              for (std::size_t w = 0; w < kLeaf; ++w) out[w] |= alongY[w] | alongZ[w];
              s.grown[layout_.slot(sx, sy, sz)] = out;
            }
        std::swap(*grown, s.grown);
      }
  }

  /// kBand on the inner slots with a band voxel within r (per axis) of a site;
  /// the rows each pass computes: pass 3 those band voxels' rows, pass 2 those
  /// within r along x of them, pass 1 those within r along y of pass 2's.
  bool markBand(Scratch& s) const {
    dilateVoxelBits(s, &Slot::siteBits, &Slot::nearBits, 2);
    dilateVoxelBits(s, &Slot::nearBits, &Slot::nearBits, 1);
    dilateVoxelBits(s, &Slot::nearBits, &Slot::nearBits, 0);
    growFaceSteps(s);
    const int m = layout_.slots, begin = layout_.firstInnerSlot(), end = layout_.endInnerSlot();
    bool any = false;
    for (int sx = 0; sx < m; ++sx)
      for (int sy = 0; sy < m; ++sy)
        for (int sz = 0; sz < m; ++sz) {
          Slot& at = slot(s, sx, sy, sz);
          const bool inner = sx >= begin && sy >= begin && sz >= begin && sx < end && sy < end && sz < end;
          at.rows2 = 0;
          if (!inner) continue;
          // The band: the voxels within halfWidth face steps of the other side (the
          // topology topologyToLevelSet gives a band).
          const std::size_t index = layout_.slot(sx, sy, sz);
          const VoxelBits inside = insideBits(at);
          for (std::size_t w = 0; w < kLeaf; ++w)
            at.nearBits[w] &= (s.grownInside[index][w] & ~inside[w]) | (s.grownOutside[index][w] & inside[w]);
          at.rows2 = rowsOf(at.nearBits);
          if (!at.rows2) continue;
          at.flags |= kBand;
          any = true;
        }
    if (!any) return false;
    dilateRowBits(s, &Slot::rows2, &Slot::rows2, 0);
    dilateRowBits(s, &Slot::rows2, &Slot::rows1, 1);
    for (Slot& at : s.slots) {
      if (at.rows1) at.flags |= kPass1;
      if (at.rows2) at.flags |= kPass2;
    }
    return true;
  }

  /// Pass 1: the offset along z of the nearest interface voxel (|offset| <= r;
  /// on a tie the lower one), on the slot's pass-1 rows.
  void nearestAlongZ(int sx, int sy, int sz, Scratch& s) const {
    const int r = layout_.reach, reach = layout_.slotReach, m = layout_.slots;
    if (2 * reach + 1 <= kMaxWindowSlots) {
      nearestAlongZBits(sx, sy, sz, s);
      return;
    }
    const int length = kLeaf + 2 * r, z0 = sz * kLeaf;
    std::array<std::uint8_t, kLeaf + 2 * kMaxReach> row{};  // sites along z from z0 - r
    std::array<int, kLeaf + 2 * kMaxReach> below{}, above{};
    std::array<bool, 2 * kMaxSlotReach + 1> siteSlot{};
    for (int d = -reach; d <= reach; ++d) {
      const int z = sz + d;
      siteSlot[static_cast<std::size_t>(d + reach)] = z >= 0 && z < m && (slot(s, sx, sy, z).flags & kSites);
    }
    const RowBits rows = slot(s, sx, sy, sz).rows1;
    for (int i = 0; i < kLeaf; ++i)
      for (int j = 0; j < kLeaf; ++j) {
        if (!((rows >> (8 * i + j)) & 1u)) continue;
        // Row entry t is voxel z0 - r + t; slot d along z starts at entry 8 (d + reach) - (8 reach - r).
        for (int d = -reach; d <= reach; ++d) {
          const int first = kLeaf * (d + reach) - (kLeaf * reach - r);
          const int from = std::max(first, 0), to = std::min(first + kLeaf, length);
          if (from >= to) continue;
          const Slot* sites = siteSlot[static_cast<std::size_t>(d + reach)] ? &slot(s, sx, sy, sz + d) : nullptr;
          const unsigned bits =
              sites ? static_cast<unsigned>(sites->siteBits[static_cast<std::size_t>(i)] >> (8 * j)) & 0xffu : 0u;
          for (int t = from; t < to; ++t)
            row[static_cast<std::size_t>(t)] = static_cast<std::uint8_t>((bits >> (t - first)) & 1u);
        }
        int last = -4 * kMaxReach;
        for (int t = 0; t < length; ++t)
          below[static_cast<std::size_t>(t)] = last = row[static_cast<std::size_t>(t)] ? t : last;
        last = 4 * kMaxReach;
        for (int t = length - 1; t >= 0; --t)
          above[static_cast<std::size_t>(t)] = last = row[static_cast<std::size_t>(t)] ? t : last;
        std::int8_t* out = &s.nearZ[layout_.voxel(sx * kLeaf + i, sy * kLeaf + j, z0)];
        for (int k = 0; k < kLeaf; ++k) {
          const int t = k + r;
          out[k] = nearerOffset(t - below[static_cast<std::size_t>(t)], above[static_cast<std::size_t>(t)] - t, r);
        }
      }
  }

  /// Pass 1 where the slots within reach along z fit one 64-bit word (half-widths up
  /// to 23, the default 3 included): each row's sites as bits (slot d's byte of
  /// siteBits at bit 8 (d + reach)), the nearest one below and above a voxel found by
  /// counting zeros instead of scanning a byte row. The same offsets as the byte scan.
  void nearestAlongZBits(int sx, int sy, int sz, Scratch& s) const {
    const int r = layout_.reach, reach = layout_.slotReach, m = layout_.slots;
    std::array<const VoxelBits*, kMaxWindowSlots> sites{};
    for (int d = -reach; d <= reach; ++d) {
      const int z = sz + d;
      if (z >= 0 && z < m && (slot(s, sx, sy, z).flags & kSites))
        sites[static_cast<std::size_t>(d + reach)] = &slot(s, sx, sy, z).siteBits;
    }
    const RowBits rows = slot(s, sx, sy, sz).rows1;
    for (int i = 0; i < kLeaf; ++i)
      for (int j = 0; j < kLeaf; ++j) {
        if (!((rows >> (8 * i + j)) & 1u)) continue;
        std::uint64_t window = 0;  // bit 8 (d + reach) + k: voxel z0 + 8 d + k
        for (int d = 0; d <= 2 * reach; ++d)
          if (const VoxelBits* bits = sites[static_cast<std::size_t>(d)])
            window |= (((*bits)[static_cast<std::size_t>(i)] >> (8 * j)) & 0xffu) << (8 * d);
        std::int8_t* out = &s.nearZ[layout_.voxel(sx * kLeaf + i, sy * kLeaf + j, sz * kLeaf)];
        for (int k = 0; k < kLeaf; ++k) {
          const int p = kLeaf * reach + k;
          const std::uint64_t atOrBelow = window & (~std::uint64_t{0} >> (63 - p));
          const std::uint64_t atOrAbove = window >> p;
          const int down = atOrBelow ? p - (63 - std::countl_zero(atOrBelow)) : 4 * kMaxReach;
          const int up = atOrAbove ? std::countr_zero(atOrAbove) : 4 * kMaxReach;
          out[k] = nearerOffset(down, up, r);
        }
      }
  }

  /// Pass 2: the nearest interface voxel in the voxel's yz-plane, on the slot's
  /// pass-2 rows. Rows are visited by increasing |dy| and the scan stops once
  /// dy^2 alone is no closer for any of the row's eight voxels: exact, and near the
  /// surface it stops after a row or two. The eight voxels along z are eight bytes of
  /// nearZ, taken together in one register (per voxel: the same candidates in the
  /// same order as a scan of its own, ties to the first).
  void nearestInPlane(int sx, int sy, int sz, Scratch& s) const {
    const int r = layout_.reach, n = layout_.n;
    const std::ptrdiff_t stride = n;  // one step along y
    const RowBits rows = slot(s, sx, sy, sz).rows2;
    // Locals, not Scratch's vectors: the stores below would make the compiler
    // reload the vectors' data pointers at every row.
    const std::int8_t* nearZ = s.nearZ.data();
    PlaneNearest* nearYZ = s.nearYZ.data();
    for (int i = 0; i < kLeaf; ++i)
      for (int j = 0; j < kLeaf; ++j) {
        if (!((rows >> (8 * i + j)) & 1u)) continue;
        const int x = sx * kLeaf + i, y = sy * kLeaf + j;
        const int down = std::min(r, y), up = std::min(r, n - 1 - y);
        const std::size_t here = layout_.voxel(x, y, sz * kLeaf);
        RowLanes bestD2 = kFarLanes, bestDz{}, bestDy{};
        auto consider = [&](int dy) {
          RowBytes bytes;
          std::memcpy(&bytes, nearZ + static_cast<std::ptrdiff_t>(here) + dy * stride, sizeof bytes);
          const RowLanes dz = __builtin_convertvector(bytes, RowLanes);
          const RowLanes d2 = dz * dz + static_cast<std::int16_t>(dy * dy);
          const RowLanes better = (dz != kNoSite) & (d2 < bestD2);
          bestD2 = (better & d2) | (~better & bestD2);
          bestDz = (better & dz) | (~better & bestDz);
          bestDy = (better & static_cast<std::int16_t>(dy)) | (~better & bestDy);
        };
        for (int step = 0; step <= r; ++step) {
          bool closerPossible = false;
          for (std::size_t k = 0; k < kLeaf; ++k) closerPossible |= step * step < bestD2[k];
          if (!closerPossible) break;
          if (step <= down) consider(-step);
          if (step > 0 && step <= up) consider(step);
        }
        for (std::size_t k = 0; k < kLeaf; ++k)
          nearYZ[here + k] = {static_cast<std::int8_t>(bestDz[k]), static_cast<std::int8_t>(bestDy[k]),
                              bestD2[k] == kFarLane ? kFar : static_cast<std::uint16_t>(bestD2[k])};
      }
  }

  /// Pass 3 and the values: the nearest interface voxel's tangent plane at each
  /// near voxel of a band slot, signs from the mask; the slot's other voxels are
  /// inactive at +-halfWidth. The nearest site is found as in pass 2, over the
  /// planes by increasing |dx|.
  std::unique_ptr<FieldLeaf> bandLeaf(const Coord& regionMin, int sx, int sy, int sz, Scratch& s) const {
    const int r = layout_.reach, n = layout_.n;
    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(n) * n;  // one step along x
    const float h = static_cast<float>(layout_.halfWidth);
    const Slot& at = slot(s, sx, sy, sz);
    auto leaf = std::make_unique<FieldLeaf>(regionMin.offsetBy(sx * kLeaf, sy * kLeaf, sz * kLeaf), h, false);
    float* values = leaf->buffer().data();
    // Locals, not Scratch's vectors: the stores to `values` would make the compiler
    // reload the vectors' data pointers at every voxel.
    const PlaneNearest* nearYZ = s.nearYZ.data();
    bool anyActive = false;
    for (int i = 0; i < kLeaf; ++i)
      for (int j = 0; j < kLeaf; ++j) {
        const unsigned near = static_cast<unsigned>(at.nearBits[static_cast<std::size_t>(i)] >> (8 * j)) & 0xffu;
        const std::uint32_t insideRow = at.rowByte(i, j);
        const int x = sx * kLeaf + i, y = sy * kLeaf + j;
        const int down = std::min(r, x), up = std::min(r, n - 1 - x);
        for (int k = 0; k < kLeaf; ++k) {
          const std::size_t here = layout_.voxel(x, y, sz * kLeaf + k);
          const bool inside = (insideRow >> k) & 1u;
          const int index = (i << 6) | (j << 3) | k;
          values[index] = inside ? -h : h;
          if (!((near >> k) & 1u)) continue;
          int best = r * r, ox = 0, oy = 0, oz = 0;  // a farther site: at least halfWidth from the surface
          auto consider = [&](int dx) {
            const PlaneNearest& e = nearYZ[static_cast<std::ptrdiff_t>(here) + dx * stride];
            if (e.d2 == kFar) return;
            const int d2 = dx * dx + e.d2;
            if (d2 < best) best = d2, ox = dx, oy = e.dy, oz = e.dz;
          };
          for (int step = 0; step <= r && step * step < best; ++step) {
            if (step <= down) consider(-step);
            if (step > 0 && step <= up) consider(step);
          }
          if (best >= r * r) continue;
          const int px = x + ox, py = y + oy, pz = sz * kLeaf + k + oz;
          const Slot& siteSlot = slot(s, px / kLeaf, py / kLeaf, pz / kLeaf);
          const SitePlane& plane =
              s.planes[siteSlot.planes + static_cast<std::uint32_t>(((px & 7) << 6) | ((py & 7) << 3) | (pz & 7))];
          const std::array<float, 3>& normal = plane.normal;
          float d = plane.distance - (normal[0] * static_cast<float>(ox) + normal[1] * static_cast<float>(oy) +
                                      normal[2] * static_cast<float>(oz));
          if (best > 0) d = inside ? std::min(d, -kInteriorFloor) : std::max(d, kInteriorFloor);
          if (std::abs(d) >= h) continue;
          values[index] = d;
          leaf->setActiveState(static_cast<openvdb::Index>(index), true);
          anyActive = true;
        }
      }
    if (!anyActive) return nullptr;
    return leaf;
  }

  const MaskGrid& mask_;
  const Layout& layout_;
  std::array<float, 2 * kBlurRadius + 1> weights_;
  std::array<float, 1u << (2 * kBlurRadius + 1)> rowBlur_{};
};

/// Chunks whose region may hold an interface: near a mask leaf, or near the
/// boundary of an active tile. Sorted, so the order is fixed.
std::vector<Coord> candidateChunks(const MaskGrid& mask, const Layout& layout) {
  const int c = layout.chunk;
  const int margin = layout.slotReach * kLeaf + kLeaf;  // a site slot next to a slot within reach
  std::vector<Coord> chunks;
  auto addAround = [&](const CoordBBox& box, bool skipInterior) {
    const Coord lo(floorDiv(box.min().x() - margin, c), floorDiv(box.min().y() - margin, c),
                   floorDiv(box.min().z() - margin, c));
    const Coord hi(floorDiv(box.max().x() + margin, c), floorDiv(box.max().y() + margin, c),
                   floorDiv(box.max().z() + margin, c));
    for (int x = lo.x(); x <= hi.x(); ++x)
      for (int y = lo.y(); y <= hi.y(); ++y)
        for (int z = lo.z(); z <= hi.z(); ++z) {
          const Coord origin(x * c, y * c, z * c);
          if (skipInterior) {
            CoordBBox reach(origin, origin.offsetBy(c - 1));
            reach.expand(margin);
            if (box.isInside(reach)) continue;  // wholly inside the tile: no interface from it
          }
          chunks.push_back(origin);
        }
  };
  for (auto leaf = mask.tree().cbeginLeaf(); leaf; ++leaf)
    addAround(CoordBBox::createCube(leaf->origin(), kLeaf), false);
  forEachActiveTile(mask.tree(), [&](const CoordBBox& box) { addAround(box, true); });
  std::sort(chunks.begin(), chunks.end());
  chunks.erase(std::unique(chunks.begin(), chunks.end()), chunks.end());
  return chunks;
}

}  // namespace

struct InterfaceBandChunks::Impl {
  Impl(const MaskGrid& mask, int halfWidth, int chunkSize)
      : layout(halfWidth, chunkSize), chunks(candidateChunks(mask, layout)), band(mask, layout) {}
  Layout layout;
  std::vector<Coord> chunks;  ///< sorted (x, y, z)
  ChunkBand band;
  tbb::enumerable_thread_specific<std::unique_ptr<Scratch>> scratch;
};

InterfaceBandChunks::InterfaceBandChunks(const MaskGrid& mask, int halfWidth, int chunkSize)
    : impl_(std::make_unique<Impl>(mask, halfWidth, chunkSize)) {}

InterfaceBandChunks::~InterfaceBandChunks() = default;

int InterfaceBandChunks::chunkSize() const { return impl_->layout.chunk; }

std::size_t InterfaceBandChunks::chunkCount() const { return impl_->chunks.size(); }

std::optional<std::pair<int, int>> InterfaceBandChunks::zRange() const {
  if (impl_->chunks.empty()) return std::nullopt;
  const auto [lo, hi] = std::minmax_element(impl_->chunks.begin(), impl_->chunks.end(),
                                            [](const Coord& a, const Coord& b) { return a.z() < b.z(); });
  return std::make_pair(lo->z(), hi->z() + impl_->layout.chunk);
}

std::size_t InterfaceBandChunks::compute(int zBegin, int zEnd, const BandLeafSink& sink,
                                         const std::function<void()>& chunkDone) {
  std::vector<Coord> chunks;
  for (const Coord& c : impl_->chunks)
    if (c.z() >= zBegin && c.z() < zEnd) chunks.push_back(c);
  std::mutex handOut;
  std::size_t withBand = 0;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, chunks.size(), 1),
      [&](const tbb::blocked_range<std::size_t>& range) {
        std::unique_ptr<Scratch>& mine = impl_->scratch.local();
        if (!mine) mine = std::make_unique<Scratch>(impl_->layout);
        for (std::size_t c = range.begin(); c != range.end(); ++c) {
          std::vector<std::unique_ptr<FieldLeaf>> leaves;
          impl_->band.compute(chunks[c], *mine, leaves);
          const bool any = !leaves.empty();
          if (any) sink(std::move(leaves));
          const std::lock_guard<std::mutex> lock(handOut);
          withBand += any ? 1 : 0;
          if (chunkDone) chunkDone();
        }
      },
      tbb::simple_partitioner());
  return withBand;
}

std::size_t computeInterfaceBand(const MaskGrid& mask, int halfWidth, int chunkSize, const BandLeafSink& sink,
                                 Interrupter* interrupter) {
  ProgressStage progress(interrupter, "distance field");
  InterfaceBandChunks chunks(mask, halfWidth, chunkSize);
  std::size_t done = 0;
  const auto total = static_cast<double>(chunks.chunkCount());
  // chunkDone runs under the hand-out lock.
  return chunks.compute(std::numeric_limits<int>::min(), std::numeric_limits<int>::max(), sink,
                        [&] { progress.update(static_cast<double>(++done), total); });
}

}  // namespace isovdb::volume
