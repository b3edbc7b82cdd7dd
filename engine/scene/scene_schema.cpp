#include "engine/scene/scene_schema.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "engine/material_catalog.hpp"
#include "engine/tread_patterns.hpp"

namespace firn {
namespace {

using Q = Quantity;
using K = ValueKind;
constexpr double kInf = std::numeric_limits<double>::infinity();

const std::vector<std::string> kBoundaries = {"sticky", "slip", "separate"};
const std::vector<std::string> kWallTypes = {"none", "sticky", "slip", "separate"};
const char* const kPenaltyStiffnessDoc =
    "contact = penalty: the spring's angular frequency omega = penalty_stiffness c / dx, c the fastest "
    "material's P-wave speed at rest; stiffer springs let the particles overlap less (the overlap that carries a "
    "pressure p is about p dx^2 / (rho c^2 penalty_stiffness^2 h), h the particle spacing) and need "
    "penalty_stiffness cfl < 1.9 to stay stable";

KeySpec wall_face(const std::string& face) {
  return {face, K::choice, Q::dimensionless, "", false, "boundary on the " + face + " face (default: `type`)",
          -kInf, kInf, false, kWallTypes};
}

// [materials.NAME] vary (engine/scene/material_variation.hpp): the noise's keys, then a relative
// amplitude for every numeric parameter a model reads.
SectionSpec vary_section() {
  const auto amplitude = [](const std::string& key, const std::string& model) {
    return KeySpec{key, K::number, Q::dimensionless, "", false,
                   "relative amplitude: " + key + " = nominal (1 + amplitude n(x))", -1, 1, true, {}, model, true};
  };
  SectionSpec vary{
      "materials.NAME.vary", false,
      "An inline table `vary = { ... }` in a [materials.NAME] table: each parameter it lists takes the value "
      "nominal (1 + amplitude n(x)) at the particle's rest position x, with n a smooth, seeded noise field in "
      "[-1, 1] (lattice value noise with correlation length `scale`: mean 0, standard deviation about 0.4; "
      "engine/noise_field.hpp). One field per table, shared by all its varied parameters: with positive "
      "amplitudes on density and strength, denser snow is also stronger; a negative amplitude anti-correlates. "
      "n is quantised into `levels` equal bins of [-1, 1], each an engine material with the bin's centre "
      "value of n (named NAME~0 ... NAME~(levels - 1) in messages, `firn check` and the .vtp `material` "
      "array). A varied modulus keeps its partner (E keeps nu, K keeps G and the reverse); at most two of E, "
      "nu, K, G vary. The same seed and scale give the same field in every table.",
      {
          {"scale", K::number, Q::length, "", true, "correlation length of the noise (its lattice spacing)", 0,
           kInf, true},
          {"seed", K::integer, Q::dimensionless, "0", false, "seed of the noise field", 0, kInf},
          {"levels", K::integer, Q::dimensionless, "8", false,
           "quantisation bins of the noise, one engine material each", 2, 64},
      }};
  for (const char* key : {"density", "E", "nu", "K", "G"}) vary.keys.push_back(amplitude(key, ""));
  for (const MaterialModelSpec& m : material_model_specs())
    for (const MaterialParameter& p : m.parameters)
      if (p.choices.empty()) vary.keys.push_back(amplitude(p.key, m.name));
  return vary;
}

std::vector<SectionSpec> build_schema() {
  std::vector<SectionSpec> s;
  s.push_back({"simulation", false, "The domain, the grid, time stepping and the transfer scheme.",
               {
                   {"domain_min", K::vector3, Q::length, "", true, "lower corner of the domain box"},
                   {"domain_max", K::vector3, Q::length, "", true, "upper corner of the domain box"},
                   {"dx", K::number, Q::length, "", true, "grid cell size", 0, kInf, true},
                   {"particles_per_cell", K::integer, Q::dimensionless, "8", false,
                    "particles per grid cell on a regular lattice: 1, 8, 27 or 64", 1, 64},
                   {"end_time", K::number, Q::time, "", true, "simulated time to run", 0, kInf, true},
                   {"frame_interval", K::number, Q::time, "", false,
                    "time between output frames (default: end_time / 100)", 0, kInf, true},
                   {"cfl", K::number, Q::dimensionless, "0.4", false,
                    "CFL number: dt = cfl dx / max(c_p + |v_p|)", 0, 1, true},
                   {"dt_max", K::number, Q::time, "0.001", false, "largest time step", 0, kInf, true},
                   {"fixed_dt", K::number, Q::time, "0.0", false,
                    "when > 0, every step uses this time step instead of the CFL one", 0, kInf},
                   {"damping", K::number, Q::rate, "0.0", false,
                    "grid velocity damping rate: each step divides the grid's velocities by 1 + damping dt "
                    "(mass-proportional damping, for quasi-static states such as a tire's static footprint; "
                    "what it takes is in energy_residual)",
                    0, kInf},
                   {"gravity", K::vector3, Q::acceleration, "[0.0, -9.81, 0.0]", false, "gravitational acceleration"},
                   {"transfer", K::choice, Q::dimensionless, "\"apic\"", false,
                    "particle-grid transfer: apic (MLS-MPM), pic or flip (FLIP/PIC blend)", -kInf, kInf, false,
                    {"apic", "pic", "flip"}},
                   {"flip_alpha", K::number, Q::dimensionless, "0.95", false, "FLIP fraction of the flip blend", 0, 1},
                   {"shape", K::choice, Q::dimensionless, "\"quadratic\"", false, "B-spline shape function",
                    -kInf, kInf, false, {"quadratic", "cubic"}},
                   {"precision", K::choice, Q::dimensionless, "\"float\"", false, "floating-point precision of the run",
                    -kInf, kInf, false, {"float", "double"}},
               }});
  s.push_back({"walls", false,
               "Domain walls: the nodes within `width` cells of a face get its boundary condition.",
               {
                   {"type", K::choice, Q::dimensionless, "\"separate\"", false,
                    "boundary on every face: none, sticky (v = 0), slip (normal velocity removed) or separate "
                    "(normal velocity removed only when approaching)",
                    -kInf, kInf, false, kWallTypes},
                   wall_face("x_min"), wall_face("x_max"), wall_face("y_min"), wall_face("y_max"),
                   wall_face("z_min"), wall_face("z_max"),
                   {"friction", K::number, Q::dimensionless, "0.0", false, "Coulomb friction coefficient of the walls",
                    0, kInf},
                   {"width", K::integer, Q::dimensionless, "3", false, "wall band thickness in cells", 1, 8},
                   {"mirror", K::boolean, Q::dimensionless, "false", false,
                    "impose the sticky and slip faces through mirrored ghost nodes: the band's innermost node row is "
                    "the wall's plane and the rows beyond it carry the image of the body (slip: its mirror image, a "
                    "frictionless symmetry plane; sticky: its velocity negated, a clamped plane), so particles next "
                    "to the wall keep their whole B-spline support and a stressed boundary converges at second "
                    "order. Faces set to none are left alone; separate faces cannot be mirrored. Keep colliders out of "
                    "a mirror band: its ghost nodes' velocities are replaced after the colliders act"},
               }});

  SectionSpec materials{"materials.NAME", false,
                        "One table per material, named by the scene; bodies refer to it by NAME. Give `preset`, "
                        "or `model`, `density` and two of E, nu, K, G. Keys given beside a preset override it; "
                        "giving any of E, nu, K, G replaces all of the preset's moduli.",
                        {
                            {"preset", K::text, Q::dimensionless, "", false, "a named parameter set (see Presets)"},
                            {"model", K::choice, Q::dimensionless, "", false, "constitutive model (required without a preset)"},
                            {"density", K::number, Q::density, "", false, "rest density", 0, kInf, true},
                            {"E", K::number, Q::pressure, "", false, "Young's modulus", 0, kInf, true},
                            {"nu", K::number, Q::dimensionless, "", false, "Poisson's ratio", -1, 0.5, true, {}, {}, true},
                            {"K", K::number, Q::pressure, "", false, "bulk modulus", 0, kInf, true},
                            {"G", K::number, Q::pressure, "", false, "shear modulus", 0, kInf, true},
                            {"color", K::vector3, Q::dimensionless, "", false,
                             "render colour [r, g, b], each in [0, 1] (default: a built-in palette)"},
                            {"contact_group", K::integer, Q::dimensionless, "0", false,
                             "contact group, 0 or 1: bodies of different groups move on their own grids and meet "
                             "through frictional contact ([contact]) instead of sticking as one continuum",
                             0, 1},
                            {"vary", K::table, Q::dimensionless, "", false,
                             "parameters that vary in space by a seeded noise field (see [materials.NAME.vary]), e.g. "
                             "`vary = { density = 0.15, p0 = 0.3, scale = \"15 mm\", seed = 1 }`"},
                        }};
  for (const MaterialModelSpec& m : material_model_specs()) {
    materials.keys[1].choices.push_back(m.name);
    for (const MaterialParameter& p : m.parameters) {
      KeySpec k{p.key, p.choices.empty() ? K::number : K::choice, p.quantity, "", !p.default_value.has_value(),
                p.doc, p.min, p.max, false, p.choices, m.name};
      if (p.default_value) {
        std::ostringstream text;
        text.precision(17);
        if (p.choices.empty()) text << *p.default_value;
        else text << '"' << p.choices.at(std::size_t(*p.default_value)) << '"';
        k.default_toml = text.str();
      }
      materials.keys.push_back(k);
    }
  }
  s.push_back(materials);
  s.push_back(vary_section());

  const std::vector<KeySpec> geometry = {
      {"shape", K::choice, Q::dimensionless, "", true,
       "sphere, box, cylinder, union (of `parts`) or difference (first of `parts` minus the others)", -kInf, kInf,
       false, {"sphere", "box", "cylinder", "union", "difference"}},
      {"center", K::vector3, Q::length, "", true, "centre", -kInf, kInf, false, {}, "sphere"},
      {"radius", K::number, Q::length, "", true, "radius", 0, kInf, true, {}, "sphere"},
      {"min", K::vector3, Q::length, "", true, "lower corner", -kInf, kInf, false, {}, "box"},
      {"max", K::vector3, Q::length, "", true, "upper corner", -kInf, kInf, false, {}, "box"},
      {"center", K::vector3, Q::length, "", true, "centre", -kInf, kInf, false, {}, "cylinder"},
      {"radius", K::number, Q::length, "", true, "radius", 0, kInf, true, {}, "cylinder"},
      {"length", K::number, Q::length, "", true, "length along the axis", 0, kInf, true, {}, "cylinder"},
      {"axis", K::choice, Q::dimensionless, "\"y\"", false, "axis direction", -kInf, kInf, false, {"x", "y", "z"},
       "cylinder"},
      {"parts", K::tables, Q::dimensionless, "", true, "array of shape tables (`bodies.parts` keys)", -kInf, kInf,
       false, {}, "union"},
      {"parts", K::tables, Q::dimensionless, "", true, "array of shape tables (`bodies.parts` keys)", -kInf, kInf,
       false, {}, "difference"},
  };
  SectionSpec bodies{"bodies", true,
                     "Solids filled with particles on the lattice of `particles_per_cell`, in file order; a body never "
                     "takes lattice sites inside an earlier body, so concentric spheres make a layered ball.",
                     {
                         {"name", K::text, Q::dimensionless, "", false, "label used in messages"},
                         {"material", K::text, Q::dimensionless, "", true, "NAME of a [materials.NAME] table"},
                         {"velocity", K::vector3, Q::velocity, "[0.0, 0.0, 0.0]", false, "initial velocity"},
                         {"angular_velocity", K::vector3, Q::angular_velocity, "[0.0, 0.0, 0.0]", false,
                          "initial angular velocity about the body's centre of mass"},
                         {"jitter", K::number, Q::dimensionless, "0.0", false,
                          "random offset of each particle, as a fraction of the lattice spacing", 0, 1},
                         {"seed", K::integer, Q::dimensionless, "0", false, "seed of the jitter", 0, kInf},
                     }};
  bodies.keys.insert(bodies.keys.end(), geometry.begin(), geometry.end());
  s.push_back(bodies);
  s.push_back({"bodies.parts", true, "A shape inside a union or difference (the same shape keys as a body).",
               geometry});

  const std::vector<std::string> kFrictionLaws = {"coulomb", "velocity_dependent"};
  s.push_back({"colliders", true, "Kinematic rigid solids that act on the grid.",
               {
                   {"name", K::text, Q::dimensionless, "", false,
                    "letters, digits and _: names its metrics.csv columns (default: colliderN)"},
                   {"shape", K::choice, Q::dimensionless, "", true, "plane (a half-space), box or cylinder", -kInf,
                    kInf, false, {"plane", "box", "cylinder"}},
                   {"point", K::vector3, Q::length, "", true, "a point on the plane", -kInf, kInf, false, {}, "plane"},
                   {"normal", K::vector3, Q::dimensionless, "", true, "normal pointing out of the solid", -kInf, kInf,
                    false, {}, "plane"},
                   {"min", K::vector3, Q::length, "", true, "lower corner at t = 0", -kInf, kInf, false, {}, "box"},
                   {"max", K::vector3, Q::length, "", true, "upper corner at t = 0", -kInf, kInf, false, {}, "box"},
                   {"center", K::vector3, Q::length, "", true, "centre at t = 0", -kInf, kInf, false, {}, "cylinder"},
                   {"radius", K::number, Q::length, "", true, "radius", 0, kInf, true, {}, "cylinder"},
                   {"length", K::number, Q::length, "", true, "length along the axis", 0, kInf, true, {}, "cylinder"},
                   {"axis", K::choice, Q::dimensionless, "\"z\"", false, "axis direction", -kInf, kInf, false,
                    {"x", "y", "z"}, "cylinder"},
                   {"velocity", K::vector3, Q::velocity, "[0.0, 0.0, 0.0]", false, "constant velocity"},
                   {"angular_velocity", K::vector3, Q::angular_velocity, "[0.0, 0.0, 0.0]", false,
                    "constant angular velocity about the centre (plane: about `point`)"},
                   {"boundary", K::choice, Q::dimensionless, "\"sticky\"", false,
                    "sticky, slip or separate (see walls)", -kInf, kInf, false, kBoundaries},
                   {"friction_law", K::choice, Q::dimensionless, "\"coulomb\"", false,
                    "coulomb, or velocity_dependent: the thesis' Eq. 4.9, mu(v) = mu0 (12101 v / (v^2 + 12100))^0.17 "
                    "with v the slip speed in mm/s",
                    -kInf, kInf, false, kFrictionLaws},
                   {"friction", K::number, Q::dimensionless, "0.0", false,
                    "friction coefficient (velocity_dependent: mu0, the value at 1 mm/s)", 0, kInf},
                   {"contact", K::choice, Q::dimensionless, "\"nodes\"", false,
                    "nodes (every grid node inside takes the boundary condition on its own) or pooled (boundary "
                    "separate only): the contact of one stiff body taken as a whole, every node inside given the "
                    "same normal velocity change, no node's material let across the surface, friction on the row "
                    "of nodes just outside with Coulomb's bound on the whole contact; with it the rolling cylinder of "
                    "`firn verify` converges and the sliding one stays within 0.15% (docs/contact.md). Not for "
                    "snow, nor for several bodies touching one collider; not with two contact groups or mirror "
                    "walls; or penalty (boundary separate only): the nodes are left alone and every particle that "
                    "overlaps the collider (a ball of half its rest spacing) is pushed out by a spring of its own "
                    "mass, friction acting on that push; it stores the energy it takes, where the node contact "
                    "dissipates some at every step (docs/contact.md, \"A penalty contact at the particles\")",
                    -kInf, kInf, false, {"nodes", "pooled", "penalty"}},
                   {"penalty_stiffness", K::number, Q::dimensionless, "1.0", false, kPenaltyStiffnessDoc, 0, 4, true},
               }});
  std::vector<std::string> treads;
  for (const TreadPattern& t : tread_patterns()) treads.push_back(t.name);
  s.push_back({"tire", false,
               "The tire of the thesis' experiment: a rigid collider with a tread pattern, its axle along z "
               "through `center`, turning so that the tread at the ground moves toward -x at `speed` (the tire "
               "rolls toward +x), or turning freely under the snow's torque (`spin = \"free\"`). Its grooves are "
               "exact at any grid size (a signed distance function). A loaded tire whose lowest point goes more "
               "than a cell below the conveyor's ground stops the run (the snow does not carry it; colliders do "
               "not touch each other). Defaults: a scaled test tire (400 mm diameter, 125 mm wide, 12 mm tread depth, 12 "
               "pitches).",
               {
                   {"tread", K::choice, Q::dimensionless, "\"angled_footstep\"", false,
                    "tread pattern (see Tread patterns)", -kInf, kInf, false, treads},
                   {"center", K::vector3, Q::length, "", true, "axle centre at t = 0"},
                   {"radius", K::number, Q::length, "0.2", false, "outer radius (top of the tread)", 0, kInf, true},
                   {"width", K::number, Q::length, "0.125", false, "tread width", 0, kInf, true},
                   {"tread_depth", K::number, Q::length, "0.012", false, "depth of the grooves", 0, kInf},
                   {"pitches", K::integer, Q::dimensionless, "12", false,
                    "repetitions of the pattern around the circumference", 1, 200},
                   {"shoulder", K::number, Q::length, "0.0", false,
                    "a slick tire's shoulder radius: the edges where the tread meets the sides rounded (0: square, "
                    "the thesis' drawing). A square shoulder cutting an elastic bed is a corner the grid resolves "
                    "and loses energy at, more the finer the grid (docs/contact.md)",
                    0, kInf},
                   {"body", K::choice, Q::dimensionless, "\"rigid\"", false,
                    "rigid (a collider) or rubber: the tread and a carcass band below it filled with particles of "
                    "`material` (and `carcass_material`), driven through a rigid rim (a sticky cylinder under the "
                    "carcass, or under an air cavity closed by two sidewalls, that takes the tire's spin and axle) "
                    "and meeting the snow through contact between contact groups (the rubber's materials go in "
                    "group 1, with this table's friction)",
                    -kInf, kInf, false, {"rigid", "rubber"}},
                   {"material", K::text, Q::dimensionless, "", true, "NAME of the rubber's [materials.NAME] table",
                    -kInf, kInf, false, {}, "rubber"},
                   {"carcass_material", K::text, Q::dimensionless, "", false,
                    "NAME of the [materials.NAME] table of the carcass band (default: `material`), e.g. a stiffer "
                    "isotropic stand-in for a belted, cord-reinforced carcass",
                    -kInf, kInf, false, {}, "rubber"},
                   {"sidewall_material", K::text, Q::dimensionless, "", false,
                    "NAME of the [materials.NAME] table of the two sidewalls (default: `material`), e.g. a "
                    "`bimodular` material, stiff in tension and soft in compression, that holds the rim up from "
                    "above and goes slack under the axle, as corded sidewalls do",
                    -kInf, kInf, false, {}, "rubber"},
                   {"carcass", K::number, Q::length, "\"20 mm\"", false,
                    "thickness of the rubber carcass below the tread (down to the rim without an air cavity)", 0,
                    kInf, true, {}, "rubber"},
                   {"rim_radius", K::number, Q::length, "", false,
                    "radius of the rigid rim. Below the carcass's inner radius (radius - tread_depth - carcass) it "
                    "leaves an air cavity between rim and carcass, closed by two rubber sidewalls (default: 0.6 "
                    "radius with a `pressure`, else the carcass's inner radius: the carcass sits on the rim)",
                    0, kInf, true, {}, "rubber"},
                   {"sidewall", K::number, Q::length, "\"8 mm\"", false,
                    "thickness of the two sidewalls that close an air cavity, from the rim to the carcass; 0: "
                    "none, an open tube of tread and carcass that nothing joins to the rim (e.g. squeezed between "
                    "plates: scenes/inflated_tube_squeeze.toml)",
                    0, kInf, false, {}, "rubber"},
                   {"pressure", K::number, Q::pressure, "0.0", false,
                    "inflation pressure: a follower pressure on the carcass's inner surface over the air cavity, "
                    "carried by Nanson's formula as it deforms (the cavity's volume change does not change it). "
                    "The sidewalls are not loaded: measured, flat rubber plates under the pressure bulge out and fold "
                    "under the axle until the rim pinches the carcass (README, Inflation), where a tire's curved, "
                    "corded sidewalls do not; they join the carcass to the rim, like the radial springs of a "
                    "flexible-ring tire model",
                    0, kInf, false, {}, "rubber"},
                   {"pressure_ramp", K::number, Q::time, "\"20 ms\"", false,
                    "time over which the pressure rises linearly from zero", 0, kInf, false, {}, "rubber"},
                   {"spin", K::choice, Q::dimensionless, "\"driven\"", false,
                    "driven (the tread turns at `speed`) or free (a towed, free-rolling wheel: its spin about the "
                    "axle turns under the snow's torque alone, from the spin whose tread speed is the conveyor's "
                    "ground speed at t = 0)",
                    -kInf, kInf, false, {"driven", "free"}},
                   {"speed", K::number, Q::velocity, "\"10 mph\"", false,
                    "surface speed of the tread (the thesis: 5, 10 or 20 mph over ground at 10 mph)", 0, kInf, false,
                    {}, "driven"},
                   {"axle", K::choice, Q::dimensionless, "\"fixed\"", false,
                    "fixed (prescribed height) or loaded (moves vertically under `load` and the snow's reaction)",
                    -kInf, kInf, false, {"fixed", "loaded"}},
                   {"load", K::number, Q::force, "", true, "downward load on the axle, the tire's weight included",
                    0, kInf, false, {}, "loaded"},
                   {"mass", K::number, Q::mass, "10.0", false, "mass of the tire and wheel", 0, kInf, true, {},
                    "loaded"},
                   {"mass", K::number, Q::mass, "10.0", false,
                    "mass of the tire and wheel (sets the default `inertia`)", 0, kInf, true, {}, "free"},
                   {"inertia", K::number, Q::moment_of_inertia, "", false,
                    "moment of inertia about the axle (default: a solid disk's, mass radius^2 / 2)", 0, kInf, true,
                    {}, "free"},
                   {"boundary", K::choice, Q::dimensionless, "\"separate\"", false,
                    "sticky, slip or separate (see walls)", -kInf, kInf, false, kBoundaries},
                   {"friction_law", K::choice, Q::dimensionless, "\"velocity_dependent\"", false,
                    "coulomb or velocity_dependent (see colliders)", -kInf, kInf, false, kFrictionLaws},
                   {"friction", K::number, Q::dimensionless, "0.25", false,
                    "friction coefficient (velocity_dependent: mu0; the thesis: 0.25 on snow, range 0.12-0.39)", 0,
                    kInf},
                   {"contact", K::choice, Q::dimensionless, "\"nodes\"", false,
                    "a rigid tire's contact: nodes (every grid node inside takes `boundary`) or penalty (boundary "
                    "separate only; see colliders): the particles that overlap the tire are pushed out by a spring, "
                    "which carries much less of the grid's numerical rolling resistance (docs/contact.md); for "
                    "eight particles per cell. No footprint map with penalty ([metrics] footprint defaults to "
                    "false)",
                    -kInf, kInf, false, {"nodes", "penalty"}},
                   {"penalty_stiffness", K::number, Q::dimensionless, "1.0", false, kPenaltyStiffnessDoc, 0, 4, true},
               }});
  s.push_back({"conveyor", false,
               "A snow bed on moving ground: the ground (y below `ground`) moves toward -x at `speed` carrying "
               "snow `depth` deep; snow enters at `inflow` on the ground's particle lattice with the ground's "
               "speed and is removed beyond `outflow` or when it comes within 4 cells of the domain's boundary, "
               "so a long roll runs in a bounded domain with a bounded particle count.",
               {
                   {"material", K::text, Q::dimensionless, "", true, "NAME of the snow's [materials.NAME] table"},
                   {"speed", K::number, Q::velocity, "\"10 mph\"", false, "ground speed (toward -x)", 0, kInf},
                   {"ground", K::number, Q::length, "", true, "height of the ground surface"},
                   {"depth", K::number, Q::length, "", true, "depth of the snow", 0, kInf, true},
                   {"z_min", K::number, Q::length, "", true, "lower lateral edge of the snow"},
                   {"z_max", K::number, Q::length, "", true, "upper lateral edge of the snow"},
                   {"inflow", K::number, Q::length, "", false, "x where snow enters (default: 4 cells inside x max)"},
                   {"outflow", K::number, Q::length, "", false,
                    "x beyond which snow is removed (default: 4 cells inside x min)"},
                   {"boundary", K::choice, Q::dimensionless, "\"sticky\"", false,
                    "boundary of the ground: sticky, slip or separate", -kInf, kInf, false, kBoundaries},
                   {"friction", K::number, Q::dimensionless, "0.0", false, "Coulomb friction of the ground", 0, kInf},
               }});
  s.push_back({"loads", true,
               "A total force on the particles inside a box when the run starts, shared in proportion to mass.",
               {
                   {"region_min", K::vector3, Q::length, "", true, "lower corner of the region"},
                   {"region_max", K::vector3, Q::length, "", true, "upper corner of the region"},
                   {"force", K::vector3, Q::force, "", true, "total force"},
                   {"ramp_time", K::number, Q::time, "0.0", false,
                    "the force grows linearly from zero over this time (0: applied at once)", 0, kInf},
               }});
  s.push_back({"contact", false,
               "Contact between the two contact groups of [materials.NAME] contact_group (multi-velocity-field "
               "contact, Bardenhagen et al. 2000): at a grid node both groups reach, the normal part of their "
               "relative velocity is removed while they approach and the tangential part slowed by friction. "
               "Used only when both groups have particles. Not with a rubber [tire]: its rubber is in group 1 "
               "and its contact takes the [tire] friction.",
               {
                   {"friction_law", K::choice, Q::dimensionless, "\"coulomb\"", false,
                    "coulomb, or velocity_dependent: the thesis' Eq. 4.9 (see [[colliders]])", -kInf, kInf, false,
                    kFrictionLaws},
                   {"friction", K::number, Q::dimensionless, "0.0", false,
                    "friction coefficient between the groups (velocity_dependent: mu0, the value at 1 mm/s)", 0,
                    kInf},
               }});
  s.push_back({"metrics", false,
               "Scene metrics beyond the standard metrics.csv columns. Every collider adds its force and "
               "torque (`NAME_fx` ... `NAME_tz`, on the collider, averaged over the frame); a [tire] adds "
               "`traction`, `vertical_load`, `axle_torque`, `motion_resistance_coefficient`, `slip_ratio`, "
               "`axle_height`, `displaced` and `accumulated` (with a [conveyor] also `sinkage`) and, with "
               "`footprint`, footprint/NNNNN.csv and .png (a rubber tire: `peak_tread_stress` and "
               "tread_stress/NNNNN.csv and .png, and on a road, the first plane among [[colliders]], "
               "`contact_length`: the length along x of the tread particles that touch it); a [conveyor] adds "
               "`injected` and `removed`; "
               "`fragments` adds `fragments` and `largest_fragment`.",
               {
                   {"displaced_distance", K::number, Q::length, "0.01", false,
                    "a particle farther than this from where the undisturbed ground would have carried it counts "
                    "as displaced (the thesis' Table 5.1)",
                    0, kInf, true},
                   {"footprint", K::boolean, Q::dimensionless, "true", false,
                    "write the tire's contact pressure map every frame (a rubber tire: its tread stress map)"},
                   {"fragments", K::boolean, Q::dimensionless, "false", false,
                    "add `fragments` (connected clusters of at least fragment_min_particles particles) and "
                    "`largest_fragment` (its particles) every frame: does the snow break into pieces?"},
                   {"fragment_link_cells", K::number, Q::dimensionless, "1.5", false,
                    "particles closer than this many grid cells belong to one fragment (1.5: the reach of a "
                    "quadratic B-spline, and more than the particle spacing at any particles_per_cell)",
                    0, 10, true},
                   {"fragment_min_particles", K::integer, Q::dimensionless, "10", false,
                    "clusters with fewer particles are spray, not fragments", 1, 1e9},
               }});
  s.push_back({"output", false, "What a run writes every frame besides metrics.csv.",
               {
                   {"particles", K::boolean, Q::dimensionless, "true", false,
                    "write particles/NNNNN.vtp (every particle's position, velocity and state; about 50 bytes "
                    "per particle per frame in single precision, 2.5 GB for the 51 frames of the full-resolution tire on snow). false "
                    "writes none: metrics.csv, summary.json, footprints, meshes and `--render` frames are "
                    "unchanged, but `firn render DIR` has nothing to draw"},
               }});
  s.push_back({"render", false, "How frames are drawn when rendering is on (`firn run --render`).",
               {
                   {"style", K::choice, Q::dimensionless, "\"spheres\"", false, "none, spheres or surface", -kInf,
                    kInf, false, {"none", "spheres", "surface"}},
                   {"color_by", K::choice, Q::dimensionless, "\"material\"", false, "colour by material or by a field",
                    -kInf, kInf, false, {"material", "speed", "J", "plastic_strain", "stress"}},
                   {"width", K::integer, Q::dimensionless, "1280", false, "image width in pixels", 16, 8192},
                   {"height", K::integer, Q::dimensionless, "720", false, "image height in pixels", 16, 8192},
                   {"fps", K::integer, Q::dimensionless, "30", false, "video frames per second", 1, 240},
                   {"color_map", K::choice, Q::dimensionless, "\"auto\"", false,
                    "colour map of a field: viridis, diverging (Moreland's cool-warm) or auto (diverging for J, "
                    "centred on 1; viridis otherwise)", -kInf, kInf, false, {"auto", "viridis", "diverging"}},
                   {"color_min", K::number, Q::dimensionless, "", false,
                    "field value at the low end of the colour map, in the field's SI unit (default: the lowest "
                    "value so far in the run)"},
                   {"color_max", K::number, Q::dimensionless, "", false,
                    "field value at the high end of the colour map (default: the highest value so far)"},
                   {"camera", K::choice, Q::dimensionless, "\"auto\"", false,
                    "camera preset, framing the particles and the bounded colliders: auto (in front, right and "
                    "above, turned so no collider blocks the view), side (level, looking along -z), three_quarter "
                    "(front right, above), contact (close and low on the first bounded collider's lowest point, "
                    "e.g. the tire's contact patch, from its front quarter) or top (looking down)",
                    -kInf, kInf, false, {"auto", "side", "three_quarter", "contact", "top"}},
                   {"camera_follow", K::boolean, Q::dimensionless, "true", false,
                    "reframe every frame so every body and the thrown snow stay in view, smoothly (the view widens "
                    "at once when something would leave it and narrows slowly); false: framed on the first frame"},
                   {"camera_position", K::vector3, Q::length, "", false,
                    "camera position (default: from the preset); with camera_target, a fixed camera"},
                   {"camera_target", K::vector3, Q::length, "", false,
                    "point the camera looks at (default: from the preset)"},
                   {"fov", K::number, Q::angle, "\"35 deg\"", false, "vertical field of view", 0, 3, true},
                   {"light_direction", K::vector3, Q::dimensionless, "", false,
                    "direction the key light travels, need not be unit length (default: down and away from the "
                    "camera, from over its shoulder)"},
                   {"shadows", K::boolean, Q::dimensionless, "true", false, "shadow-mapped key light"},
                   {"ambient_occlusion", K::boolean, Q::dimensionless, "true", false,
                    "screen-space ambient occlusion, so particles read as a volume"},
                   {"ground", K::boolean, Q::dimensionless, "true", false, "draw a ground plane"},
                   {"ground_height", K::number, Q::length, "", false,
                    "height (y) of the ground plane (default: the domain's floor)"},
                   {"legend", K::boolean, Q::dimensionless, "true", false,
                    "draw the legend (materials or colour bar) and the time"},
                   {"cutaway", K::boolean, Q::dimensionless, "false", false,
                    "hide the particles on the camera's side of the plane through the camera target across the axis "
                    "nearest the view direction, showing the inside (e.g. a snowball's layers)"},
                   {"sphere_scale", K::number, Q::dimensionless, "1.2", false,
                    "sphere diameter in particle spacings (dx / cube root of particles_per_cell)", 0, 10, true},
                   {"subsurface", K::boolean, Q::dimensionless, "true", false,
                    "--render surface: shade snow with the approximate subsurface scattering term (wrap lighting and "
                    "Henyey-Greenstein single scattering); false: Lambertian snow"},
                   {"snow_grain", K::number, Q::length, "0.001", false,
                    "--render surface: size of the snow grains (cells in material coordinates, each with its own "
                    "facet tilt, one in five sparkling)", 0, 0.1, true},
               }});
  return s;
}

std::string unit_text(const KeySpec& k) {
  if (k.kind == ValueKind::choice || k.kind == ValueKind::text || k.kind == ValueKind::table ||
      k.kind == ValueKind::tables || k.kind == ValueKind::boolean)
    return "";
  return si_unit(k.quantity);
}

const char* kind_text(ValueKind k) {
  switch (k) {
    case ValueKind::number: return "number";
    case ValueKind::integer: return "integer";
    case ValueKind::vector3: return "[x, y, z]";
    case ValueKind::choice: return "choice";
    case ValueKind::text: return "string";
    case ValueKind::boolean: return "boolean";
    case ValueKind::table: return "table";
    case ValueKind::tables: return "array of tables";
  }
  return "";
}

std::string escape_bars(std::string s) {
  for (std::size_t i = s.find('|'); i != std::string::npos; i = s.find('|', i + 2)) s.replace(i, 1, "\\|");
  return s;
}

}  // namespace

const std::vector<SectionSpec>& scene_schema() {
  static const std::vector<SectionSpec> schema = build_schema();
  return schema;
}

const SectionSpec& scene_section(const std::string& name) {
  for (const auto& s : scene_schema())
    if (s.name == name) return s;
  throw std::logic_error("no scene section '" + name + "'");
}

std::string scene_reference_markdown() {
  std::ostringstream md;
  md << "# Scene file reference\n\n"
        "Generated by `firn help scene-keys` from the table the scene validator uses "
        "(engine/scene/scene_schema.cpp, engine/material_catalog.cpp); do not edit by hand.\n\n"
        "Scene files are TOML. Numbers are SI; a string `\"VALUE UNIT\"` is converted, e.g. `\"70 mm\"`, "
        "`\"0.4 g/cm^3\"`, `\"0.078 MPa\"`, `\"6000 mm/s\"`, `\"10 mph\"`, `\"0.5 ms\"`, `\"30 deg\"`; "
        "a vector's components may each carry a unit. Keys marked *required* have no default; an "
        "empty default means the key is optional.\n\n";
  for (const SectionSpec& s : scene_schema()) {
    md << "## " << (s.array ? "[[" : "[") << s.name << (s.array ? "]]" : "]") << "\n\n" << s.doc << "\n\n";
    if (s.keys.empty()) continue;
    md << "| key | for | type | unit | default | range / choices | meaning |\n|---|---|---|---|---|---|---|\n";
    for (const KeySpec& k : s.keys) {
      std::ostringstream range;
      if (!k.choices.empty()) {
        for (std::size_t i = 0; i < k.choices.size(); ++i) range << (i ? ", " : "") << k.choices[i];
      } else if (k.min > -kInf || k.max < kInf) {
        range << (k.min_exclusive || k.min == -kInf ? "(" : "[") << k.min << ", " << k.max
              << (k.max_exclusive || k.max == kInf ? ")" : "]");
      }
      md << "| `" << k.key << "` | " << k.applies_to << " | " << kind_text(k.kind) << " | " << unit_text(k) << " | "
         << (k.required ? "*required*" : escape_bars(k.default_toml)) << " | " << escape_bars(range.str()) << " | "
         << escape_bars(k.doc) << " |\n";
    }
    md << "\n";
  }
  md << "## Tread patterns\n\nUse as `tread = \"NAME\"` in [tire]; blocks are drawn in engine/tread_patterns.cpp.\n\n"
        "| tread | blocks per pitch | description |\n|---|---|---|\n";
  for (const TreadPattern& t : tread_patterns())
    md << "| `" << t.name << "` | " << t.blocks.size() << " | " << escape_bars(t.doc) << " |\n";
  md << "\n";
  md << "## Material presets\n\nUse as `preset = \"NAME\"` in a `[materials.NAME]` table.\n\n"
        "| preset | model | values (SI) | source |\n|---|---|---|---|\n";
  for (const MaterialPreset& p : material_presets()) {
    md << "| `" << p.name << "` | " << p.model << " | ";
    bool first = true;
    const MaterialModelSpec* model = find_material_model(p.model);
    for (const auto& [key, value] : p.values) {
      md << (first ? "" : ", ") << key << " = ";
      first = false;
      // C++17 lambdas cannot capture a structured binding (clang refuses): capture a name for it.
      const auto param = std::find_if(model->parameters.begin(), model->parameters.end(),
                                      [&name = key](const MaterialParameter& q) { return q.key == name; });
      if (param != model->parameters.end() && !param->choices.empty()) md << param->choices.at(std::size_t(value));
      else md << value;
    }
    md << " | " << escape_bars(p.doc) << " |\n";
  }
  return md.str();
}

}  // namespace firn
