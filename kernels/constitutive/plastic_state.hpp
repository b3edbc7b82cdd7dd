// The per-particle plastic state a constitutive model may keep beside F (DESIGN.md section 4).
// Every model's kernels take it; elastic models ignore it. A model declares the fields it keeps
// (kUsesAlpha, kUsesJp) and the engine allocates only those particle attributes.
//
// The model interface (all FIRN_HD, T the precision):
//   static constexpr const char* kName;          scene name of the model
//   static constexpr bool kPlastic;              true: project() must run after each F update
//   static constexpr bool kUsesAlpha, kUsesJp;   which PlasticState fields persist
//   Mat3<T> kirchhoff(const Mat3<T>& F, const PlasticState<T>&) const;     tau = J sigma
//   T energy_density(const Mat3<T>& F, const PlasticState<T>&) const;      per rest volume
//   T p_wave_modulus(const PlasticState<T>&) const;   K + 4G/3 with the current hardening
//   bool project(Mat3<T>& F, PlasticState<T>&) const; (kPlastic only) F holds the trial elastic
//       deformation gradient on entry and the returned elastic one on exit; returns whether it
//       changed F and the state (false on the elastic path, so the engine writes nothing back).
#pragma once

namespace firn {

template <class T>
struct PlasticState {
  T alpha = T(0);  // equivalent plastic strain (J2 models)
  T Jp = T(1);     // plastic volume ratio J_P = det F_P (Stomakhin snow)
};

}  // namespace firn
