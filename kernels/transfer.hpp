// Particle-grid transfer schemes and the grid channels each one needs.
//   apic: affine particle-in-cell / MLS-MPM (Jiang et al. 2015; Hu et al. 2018), the default;
//   pic:  plain PIC, particle velocity = interpolated grid velocity (dissipative);
//   flip: FLIP blended with PIC, v_p <- alpha (v_p + sum w (v_i - v_i_old)) + (1 - alpha) v_pic
//         (Brackbill and Ruppel 1986; Stomakhin et al. 2013 use alpha = 0.95).
// Forces use the MLS-MPM stress term in every scheme; the velocity gradient for the F update is
// the MLS one, C = D^-1 sum w v_i (x_i - x_p)^T.
#pragma once

namespace firn {

enum class Transfer { apic, pic, flip };

// Grid node channels. After P2G: mass and momentum (including the stress impulse); FLIP also
// carries the momentum without the impulse. The grid update turns momenta into velocities in place.
// Groups of four lanes, so that kernels update a node with short vector operations.
template <Transfer kTransfer>
struct GridChannels {
  static constexpr int kMass = 0;
  static constexpr int kVelocity = 1;     // 3 channels: momentum after P2G, velocity after update
  static constexpr int kOldVelocity = 5;  // FLIP only, 3 channels after a pad
  static constexpr int kCount = kTransfer == Transfer::flip ? 8 : 4;
  // What G2P reads per node: velocity and a zero pad (and the old velocity and a pad for FLIP).
  static constexpr int kGatherCount = kTransfer == Transfer::flip ? 8 : 4;
  // P2G writes lanes 0-3 as (mass, momentum) and lanes 4-7 as (pad, old momentum); G2P reads
  // velocity from gather lanes 0-2 and old velocity from 4-6.
  static_assert(kMass == 0 && kVelocity == 1 && kOldVelocity == 5, "kernels assume this four-lane layout");
};

}  // namespace firn
