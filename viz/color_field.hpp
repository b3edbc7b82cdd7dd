// The colour-by fields (`[render] color_by`): their names, legend titles and values.
#pragma once

#include <string>
#include <vector>

#include "engine/particle_fields.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn::viz {

// "speed (m/s)", "J", "plastic strain", "von Mises stress (Pa)" for the fields speed, J,
// plastic_strain and stress.
std::string color_field_title(const std::string& field);

// The field of every particle into `out` (resized); plastic_strain is 0 where the materials keep none.
template <class T>
void color_field_values(const ParticleView<T>& pv, const std::string& field, std::vector<float>& out) {
  out.resize(pv.n);
  for (std::size_t p = 0; p < pv.n; ++p) {
    double v = 0;
    if (field == "speed") v = std::sqrt(double(pv.v[0][p]) * pv.v[0][p] + double(pv.v[1][p]) * pv.v[1][p] +
                                        double(pv.v[2][p]) * pv.v[2][p]);
    else if (field == "J") v = particle_total_J(pv, p);
    else if (field == "plastic_strain") v = pv.alpha ? pv.alpha[p] : 0;
    else if (field == "stress") v = particle_von_mises(pv, p);
    out[p] = float(v);
  }
}

}  // namespace firn::viz
