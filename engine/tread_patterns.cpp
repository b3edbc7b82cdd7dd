#include "engine/tread_patterns.hpp"

#include <stdexcept>

namespace firn {
namespace {

TreadBlock<double> block(std::initializer_list<std::pair<double, double>> vertices) {
  TreadBlock<double> b;
  for (const auto& [u, w] : vertices) b.add_vertex(u, w);
  return b;
}

// Lateral bands of the six-rib tread: six ribs of equal width, five grooves of 6% of the width.
constexpr double kGroove = 0.06, kRib = (1.0 - 5 * kGroove) / 6;
double rib_lo(int i) { return -0.5 + i * (kRib + kGroove); }
double rib_hi(int i) { return rib_lo(i) + kRib; }

std::vector<TreadPattern> build() {
  std::vector<TreadPattern> p;
  // Angled footstep: one angled block on each half, the right one half a pitch behind the left, so
  // that some block is always in contact. The centre end of a block leads and its shoulder end
  // trails by 0.3 pitch: the blocks dig in and sweep snow out to the sides.
  p.push_back({"angled_footstep",
               "two staggered angled blocks per pitch, centre end leading: digs in, throws snow sideways, "
               "always a block in contact",
               {block({{0.05, -0.47}, {0.45, -0.47}, {0.75, -0.03}, {0.35, -0.03}}),
                block({{0.55, 0.47}, {0.95, 0.47}, {1.25, 0.03}, {0.85, 0.03}})}});
  // Bowtie: a flat central block between two triangles whose tips point at it; half a pitch of
  // bare carcass between rows, so contact is not continuous.
  p.push_back({"bowtie",
               "a flat central block between two triangles pointing at it, then half a pitch without tread: "
               "spreads the load in the centre, contact not continuous",
               {block({{0.1, -0.12}, {0.6, -0.12}, {0.6, 0.12}, {0.1, 0.12}}),
                block({{0.1, -0.47}, {0.6, -0.47}, {0.35, -0.16}}),
                block({{0.1, 0.47}, {0.35, 0.16}, {0.6, 0.47}})}});
  // Six rib: two rows per pitch of four angled inner blocks and two square shoulder blocks, with
  // circumferential grooves between the ribs and lateral grooves between the rows.
  TreadPattern six{"six_rib",
                   "six ribs: four angled inner blocks and two square shoulder blocks per row, two rows per pitch, "
                   "grooves between all of them: several blocks always in contact",
                   {}};
  for (double u0 : {0.05, 0.55}) {
    for (int rib : {0, 5}) six.blocks.push_back(block({{u0 + 0.02, rib_lo(rib)}, {u0 + 0.37, rib_lo(rib)},
                                                        {u0 + 0.37, rib_hi(rib)}, {u0 + 0.02, rib_hi(rib)}}));
    for (int rib : {1, 2, 3, 4}) {
      // The end nearer the centre leads by 0.08 pitch.
      const double lo = rib_lo(rib), hi = rib_hi(rib);
      const double lead_lo = rib < 3 ? 0.0 : 0.08, lead_hi = rib < 3 ? 0.08 : 0.0;
      six.blocks.push_back(block({{u0 + lead_lo, lo}, {u0 + 0.35 + lead_lo, lo}, {u0 + 0.35 + lead_hi, hi},
                                  {u0 + lead_hi, hi}}));
    }
  }
  p.push_back(six);
  p.push_back({"slick", "no tread: a plain cylinder (a reference for the patterns)", {}});
  return p;
}

}  // namespace

const std::vector<TreadPattern>& tread_patterns() {
  static const std::vector<TreadPattern> patterns = build();
  return patterns;
}

const TreadPattern* find_tread_pattern(const std::string& name) {
  for (const TreadPattern& p : tread_patterns())
    if (p.name == name) return &p;
  return nullptr;
}

TireShape<double> make_tire_shape(const std::string& pattern, double radius, double width, double tread_depth,
                                  int pitches) {
  const TreadPattern* p = find_tread_pattern(pattern);
  if (!p) throw std::invalid_argument("unknown tread pattern '" + pattern + "'");
  if (int(p->blocks.size()) > kMaxTreadBlocks) throw std::logic_error("tread pattern with too many blocks");
  if (!(radius > tread_depth && tread_depth >= 0 && width > 0 && pitches > 0))
    throw std::invalid_argument("tire dimensions: need radius > tread_depth >= 0, width > 0, pitches > 0");
  TireShape<double> t;
  t.radius = radius;
  t.width = width;
  t.tread_depth = tread_depth;
  t.pitches = pitches;
  t.block_count = int(p->blocks.size());
  for (std::size_t b = 0; b < p->blocks.size(); ++b) t.blocks[b] = p->blocks[b];
  return t;
}

}  // namespace firn
