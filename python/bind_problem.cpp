// What a user specifies: Geometry, the material laws and Material, StickCriterion, Problem, and
// the solver's tolerances (SolverOptions).
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "puncture/material.hpp"
#include "puncture/options.hpp"
#include "puncture/problem.hpp"

namespace puncture::python {

namespace {

PartTwoEquation part_two_equation_of(const std::variant<PartTwoEquation, std::string>& v) {
  if (const auto* e = std::get_if<PartTwoEquation>(&v)) return *e;
  const auto& text = std::get<std::string>(v);
  if (text == "ring-balance") return PartTwoEquation::RingBalance;
  if (text == "paper-eq18") return PartTwoEquation::PaperEq18;
  throw py::value_error(fmt::format(
      "part_two_equation: expected PartTwoEquation, 'ring-balance' or 'paper-eq18', got '{}'",
      text));
}

// The CLI's --stick forms: none | always | coulomb | force:<N> | depth:<mm> | edge-tension:<N/mm>.
StickCriterion stick_of(const std::variant<StickCriterion, std::string>& v) {
  if (const auto* s = std::get_if<StickCriterion>(&v)) return *s;
  const auto& text = std::get<std::string>(v);
  if (text == "none") return {StickRule::None, 0.0};
  if (text == "always") return {StickRule::Always, 0.0};
  if (text == "coulomb") return {StickRule::Coulomb, 0.0};
  const auto colon = text.find(':');
  const auto rule = text.substr(0, colon);
  const auto value = colon == std::string::npos ? std::string() : text.substr(colon + 1);
  StickCriterion s;
  if (rule == "force")
    s.rule = StickRule::Force;
  else if (rule == "depth")
    s.rule = StickRule::Depth;
  else if (rule == "edge-tension")
    s.rule = StickRule::EdgeTension;
  std::size_t used = 0;
  bool number = false;
  try {
    s.threshold = std::stod(value, &used);
    number = used == value.size();
  } catch (const std::exception&) {
  }
  if (s.rule == StickRule::None || !number)
    throw py::value_error(fmt::format(
        "stick: expected none, always, force:<N>, depth:<mm>, edge-tension:<N/mm> or coulomb, "
        "got '{}'",
        text));
  return s;
}

std::string law_repr(const MaterialLaw& law) {
  return std::visit(
      [](const auto& l) -> std::string {
        using L = std::decay_t<decltype(l)>;
        if constexpr (std::is_same_v<L, Gent>) return fmt::format("Gent(j_lim={:g})", l.j_lim);
        if constexpr (std::is_same_v<L, MooneyRivlin>)
          return fmt::format("MooneyRivlin(alpha={:g})", l.alpha);
        if constexpr (std::is_same_v<L, Yeoh>)
          return fmt::format("Yeoh(c2={:g}, c3={:g})", l.c2, l.c3);
        if constexpr (std::is_same_v<L, Ogden>)
          return fmt::format(
              "Ogden(mu=[{:g}], alpha=[{:g}])", fmt::join(l.mu, ", "), fmt::join(l.alpha, ", "));
        if constexpr (std::is_same_v<L, ArrudaBoyce>)
          return fmt::format("ArrudaBoyce(n={:g})", l.n);
        if constexpr (std::is_same_v<L, GentGent>)
          return fmt::format("GentGent(j_lim={:g}, beta={:g})", l.j_lim, l.beta);
        return "NeoHookean()";
      },
      law);
}

std::string geometry_repr(const Geometry& g) {
  return fmt::format(
      "Geometry(clamp_radius_mm={:g}, thickness_mm={:g})", g.clamp_radius_mm, g.thickness_mm);
}

std::string indenter_repr(const Indenter& indenter) {
  struct Repr {
    std::string operator()(const FlatPunch& p) const {
      if (p.fillet_radius_mm > 0.0)
        return fmt::format(
            "FlatPunch(radius_mm={:g}, fillet_radius_mm={:g})", p.radius_mm, p.fillet_radius_mm);
      return fmt::format("FlatPunch(radius_mm={:g})", p.radius_mm);
    }
    std::string operator()(const SphereTipped& p) const {
      return fmt::format("SphereTipped(radius_mm={:g})", p.radius_mm);
    }
    std::string operator()(const Ball& p) const {
      return fmt::format(
          "Ball(radius_mm={:g}, ball_radius_mm={:g})", p.radius_mm, p.ball_radius_mm);
    }
    std::string operator()(const Cone& p) const {
      return fmt::format("Cone(radius_mm={:g}, half_angle_deg={:g}, tip_radius_mm={:g})",
                         p.radius_mm,
                         p.half_angle_deg,
                         p.tip_radius_mm);
    }
  };
  return std::visit(Repr{}, indenter);
}

std::string material_repr(const Material& m) {
  return fmt::format(
      "Material(shear_modulus_mpa={:g}, law={})", m.shear_modulus_mpa, law_repr(m.law));
}

std::string stick_repr(const StickCriterion& s) {
  if (s.rule == StickRule::None || s.rule == StickRule::Always || s.rule == StickRule::Coulomb)
    return fmt::format("StickCriterion('{}')", to_string(s.rule));
  return fmt::format("StickCriterion('{}:{:g}')", to_string(s.rule), s.threshold);
}

// Preload::inflated_state from Python: 'first', 'last' or k >= 1 (the library validates k).
int inflated_state_of(const py::object& value) {
  if (py::isinstance<py::str>(value)) {
    const std::string name = value.cast<std::string>();
    if (name == "first") return 1;
    if (name == "last") return kLastInflatedState;
    throw py::value_error("inflated_state: must be 'first', 'last' or a number >= 1, got '" + name +
                          "'");
  }
  if (py::isinstance<py::bool_>(value) || !py::isinstance<py::int_>(value))
    throw py::value_error("inflated_state: must be 'first', 'last' or a number >= 1");
  return value.cast<int>();
}

std::string preload_repr(const Preload& p) {
  std::string out = fmt::format("Preload(prestretch={:g}", p.prestretch);
  if (p.pressure_mpa != 0.0) out += fmt::format(", pressure_mpa={:g}", p.pressure_mpa);
  if (p.inflated_state != 1)
    out += p.inflated_state == kLastInflatedState
               ? std::string(", inflated_state='last'")
               : fmt::format(", inflated_state={}", p.inflated_state);
  if (p.gas_volume_mm3)
    out += fmt::format(", gas_volume_mm3={:g}, atmospheric_pressure_mpa={:g}",
                       *p.gas_volume_mm3,
                       p.atmospheric_pressure_mpa);
  return out + ")";
}

// By value: pybind11 2.10 cannot vectorize a function with a const reference argument.
double uniaxial_mpa(Material m, double stretch) {
  return m.shear_modulus_mpa * uniaxial_stress(m.law, stretch);
}
double equibiaxial_mpa(Material m, double stretch) {
  return m.shear_modulus_mpa * equibiaxial_stress(m.law, stretch);
}
double radial_mpa(Material m, double l1, double l2) {
  return m.shear_modulus_mpa * membrane_stress(m.law, l1, l2).s1;
}
double hoop_mpa(Material m, double l1, double l2) {
  return m.shear_modulus_mpa * membrane_stress(m.law, l1, l2).s2;
}
double first_invariant_of(double l1, double l2) { return first_invariant(l1, l2); }

using Stretches = py::array_t<double, py::array::forcecast>;

// The result of py::vectorize for array arguments, as an array (a 0-d one for scalars).
py::array_t<double> as_array(py::object result) { return py::array_t<double>::ensure(result); }

// Each elementwise function is defined twice, for floats (-> float) and for arrays or lists
// (-> numpy.ndarray, broadcast as numpy does): py::vectorize alone documents "-> object".  The
// float overload takes floats only (noconvert), so a one-element array stays an array.
template <class Class>
void def_elementwise(Class& c, const char* name, double (*f)(Material, double), const char* arg,
                     const char* doc) {
  c.def(name, f, py::arg(arg).noconvert(), doc);
  c.def(
      name,
      [f](const Material& m, const Stretches& x) { return as_array(py::vectorize(f)(m, x)); },
      py::arg(arg));
}

template <class Class>
void def_elementwise(Class& c, const char* name, double (*f)(Material, double, double),
                     const char* doc) {
  c.def(name, f, py::arg("lambda1").noconvert(), py::arg("lambda2").noconvert(), doc);
  c.def(
      name,
      [f](const Material& m, const Stretches& l1, const Stretches& l2) {
        return as_array(py::vectorize(f)(m, l1, l2));
      },
      py::arg("lambda1"),
      py::arg("lambda2"));
}

template <class T>
void copyable(py::class_<T>& c) {
  c.def("__copy__", [](const T& x) { return T(x); });
  c.def(
      "__deepcopy__", [](const T& x, py::dict) { return T(x); }, py::arg("memo"));
}

// A probe shape's outline(): its meridian as (r [mm], height above the tip [mm]) pairs.
template <class Shape>
void def_outline(py::class_<Shape>& c) {
  c.def(
      "outline",
      [](const Shape& shape) {
        std::vector<std::pair<double, double>> points;
        for (const auto& p : outline(Indenter{shape})) points.emplace_back(p.r_mm, p.height_mm);
        return points;
      },
      "The meridian from the tip (r = 0) to where the vertical shank begins: a list of\n"
      "(r [mm], height above the tip [mm]), curved parts in 24 chords each (to draw it to scale)");
}

}  // namespace

std::string invalid_input_message(const std::vector<ValidationError>& errors) {
  if (errors.empty()) return {};
  std::string all = "invalid input:";
  for (const auto& e : errors) all += fmt::format("\n  {}: {}", e.parameter, e.message);
  return all;
}

std::string invalid_input_message(const Problem& problem) {
  return invalid_input_message(validation_errors(problem));
}

void check_problem(const Problem& problem) {
  if (const auto message = invalid_input_message(problem); !message.empty())
    throw py::value_error(message);
}

void bind_problem(py::module_& m) {
  py::class_<Geometry> geometry(m, "Geometry", "The membrane's dimensions [mm]");
  geometry
      .def(py::init([](double clamp, double thickness) {
             return Geometry{clamp, thickness};
           }),
           py::arg("clamp_radius_mm") = Geometry{}.clamp_radius_mm,
           py::arg("thickness_mm") = Geometry{}.thickness_mm)
      .def_readwrite("clamp_radius_mm",
                     &Geometry::clamp_radius_mm,
                     "inner radius A of the clamping rings [mm]")
      .def_readwrite(
          "thickness_mm", &Geometry::thickness_mm, "undeformed membrane thickness H [mm]")
      .def("__repr__", &geometry_repr);
  copyable(geometry);

  py::class_<Preload> preload(
      m, "Preload", "How the membrane is loaded before indentation: pre-stretch and gas pressure");
  preload
      .def(py::init([](double prestretch,
                       double pressure_mpa,
                       std::optional<double>
                           gas_volume_mm3,
                       double atmospheric_pressure_mpa,
                       const py::object& inflated_state) {
             Preload p;
             p.prestretch = prestretch;
             p.pressure_mpa = pressure_mpa;
             p.inflated_state = inflated_state_of(inflated_state);
             p.gas_volume_mm3 = gas_volume_mm3;
             p.atmospheric_pressure_mpa = atmospheric_pressure_mpa;
             return p;
           }),
           py::arg("prestretch") = Preload{}.prestretch,
           py::arg("pressure_mpa") = Preload{}.pressure_mpa,
           py::arg("gas_volume_mm3") = py::none(),
           py::arg("atmospheric_pressure_mpa") = Preload{}.atmospheric_pressure_mpa,
           py::arg("inflated_state") = "first")
      .def_readwrite("prestretch",
                     &Preload::prestretch,
                     "equibiaxial pre-stretch L0 (>= 1): the stress-free disc of radius A / L0 "
                     "is stretched by L0 and clamped at A")
      .def_readwrite("pressure_mpa",
                     &Preload::pressure_mpa,
                     "gas pressure p under the membrane [MPa] (>= 0), held: inflated first, then "
                     "indented at its pole; depths from the inflated pole (sphere-tipped probe)")
      .def_property(
          "inflated_state",
          [](const Preload& p) -> py::object {
            if (p.inflated_state == kLastInflatedState) return py::str("last");
            if (p.inflated_state == 1) return py::str("first");
            return py::int_(p.inflated_state);
          },
          [](Preload& p, const py::object& value) { p.inflated_state = inflated_state_of(value); },
          "which inflated state at pressure_mpa is indented where there are several: 'first' "
          "(reached by inflating slowly from flat), 'last' (the stiffest) or k >= 1, the k-th in "
          "order of pole stretch")
      .def_readwrite("gas_volume_mm3",
                     &Preload::gas_volume_mm3,
                     "a sealed chamber instead of a held pressure: V0, the gas volume under the "
                     "flat membrane [mm^3] (> 0), closed at the inflated state of pressure_mpa; "
                     "isothermal, (p + p_atm)(V0 + V) stays fixed.  None: pressure held")
      .def_readwrite("atmospheric_pressure_mpa",
                     &Preload::atmospheric_pressure_mpa,
                     "atmospheric pressure p_atm [MPa] (> 0): the gauge pressures' offset in the "
                     "sealed chamber's gas law (with gas_volume_mm3 only)")
      .def("__repr__", &preload_repr);
  copyable(preload);

  // Indenter shapes are values (read-only: assign a new one to Problem.indenter).
  py::class_<FlatPunch> flat_punch(
      m,
      "FlatPunch",
      "The paper's flat-ended cylindrical indenter, its corner sharp or rounded by a fillet");
  flat_punch
      .def(py::init([](double radius_mm, double fillet_radius_mm) {
             return FlatPunch{radius_mm, fillet_radius_mm};
           }),
           py::arg("radius_mm") = FlatPunch{}.radius_mm,
           py::arg("fillet_radius_mm") = FlatPunch{}.fillet_radius_mm)
      .def_readonly("radius_mm", &FlatPunch::radius_mm, "cylinder radius a [mm]")
      .def_readonly("fillet_radius_mm",
                    &FlatPunch::fillet_radius_mm,
                    "corner fillet radius rho [mm] (0: the sharp corner)")
      .def("__repr__", [](const FlatPunch& p) { return indenter_repr(p); });
  copyable(flat_punch);
  def_outline(flat_punch);
  py::class_<SphereTipped> sphere_tipped(
      m,
      "SphereTipped",
      "A cylinder ending in a hemisphere of the same radius (held where it touched with a stick\n"
      "rule, no gas pressure; sliding with Coulomb slip on the hemisphere and the cylinder side)");
  sphere_tipped
      .def(py::init([](double radius_mm) { return SphereTipped{radius_mm}; }),
           py::arg("radius_mm") = SphereTipped{}.radius_mm)
      .def_readonly("radius_mm", &SphereTipped::radius_mm, "hemisphere and cylinder radius a [mm]")
      .def("__repr__", [](const SphereTipped& p) { return indenter_repr(p); });
  copyable(sphere_tipped);
  def_outline(sphere_tipped);
  py::class_<Ball> ball(m,
                        "Ball",
                        "A sphere of radius ball_radius_mm on a rod of radius radius_mm (held "
                        "or sliding;\nsolved up to the ball's equator)");
  ball.def(py::init([](double radius_mm, double ball_radius_mm) {
             return Ball{radius_mm, ball_radius_mm};
           }),
           py::arg("radius_mm"),
           py::arg("ball_radius_mm"))
      .def_readonly("radius_mm", &Ball::radius_mm, "rod radius a [mm]")
      .def_readonly("ball_radius_mm", &Ball::ball_radius_mm, "ball radius RB [mm] (> a)")
      .def("__repr__", [](const Ball& p) { return indenter_repr(p); });
  copyable(ball);
  def_outline(ball);
  py::class_<Cone> cone(m,
                        "Cone",
                        "A cone of half-angle half_angle_deg with a spherical tip of radius\n"
                        "tip_radius_mm tangent to it, on a shank of radius radius_mm "
                        "(held or sliding;\nsolved until the contact reaches the shank)");
  cone.def(py::init([](double radius_mm, double half_angle_deg, double tip_radius_mm) {
             return Cone{radius_mm, half_angle_deg, tip_radius_mm};
           }),
           py::arg("radius_mm"),
           py::arg("half_angle_deg"),
           py::arg("tip_radius_mm"))
      .def_readonly("radius_mm", &Cone::radius_mm, "shank radius a [mm]")
      .def_readonly("half_angle_deg", &Cone::half_angle_deg, "half-angle from the axis [deg]")
      .def_readonly("tip_radius_mm", &Cone::tip_radius_mm, "tip sphere radius RT [mm] (> 0)")
      .def("__repr__", [](const Cone& p) { return indenter_repr(p); });
  copyable(cone);
  def_outline(cone);

  py::class_<Gent> gent(m, "Gent", "Gent law W/G = -(J_lim/2) ln(1 - (I1 - 3)/J_lim)");
  gent.def(py::init([](double j_lim) { return Gent{j_lim}; }), py::arg("j_lim") = Gent{}.j_lim)
      .def_readwrite("j_lim", &Gent::j_lim, "limiting value of I1 - 3")
      .def("__repr__", [](const Gent& g) { return law_repr(g); });
  copyable(gent);
  py::class_<NeoHookean> neo(m, "NeoHookean", "neo-Hookean law W/G = (I1 - 3)/2");
  neo.def(py::init<>()).def("__repr__", [](const NeoHookean& n) { return law_repr(n); });
  copyable(neo);
  py::class_<MooneyRivlin> mr(
      m, "MooneyRivlin", "Mooney-Rivlin law W/G = (1 - alpha)(I1 - 3)/2 + alpha (I2 - 3)/2");
  mr.def(py::init([](double alpha) { return MooneyRivlin{alpha}; }),
         py::arg("alpha") = MooneyRivlin{}.alpha)
      .def_readwrite("alpha", &MooneyRivlin::alpha, "C2 / (C1 + C2), in [0, 1)")
      .def("__repr__", [](const MooneyRivlin& r) { return law_repr(r); });
  copyable(mr);
  py::class_<Yeoh> yeoh(
      m,
      "Yeoh",
      "Yeoh law W/G = x/2 + c2 x^2 + c3 x^3, x = I1 - 3 (c2 = C20/G, c3 = C30/G,\n"
      "G = 2 C10; both >= 0).  Material.yeoh(c10, c20, c30) takes the MPa values.");
  yeoh.def(py::init([](double c2, double c3) {
             return Yeoh{c2, c3};
           }),
           py::arg("c2") = 0.0,
           py::arg("c3") = 0.0)
      .def_readwrite("c2", &Yeoh::c2, "C20 / G")
      .def_readwrite("c3", &Yeoh::c3, "C30 / G")
      .def("__repr__", [](const Yeoh& y) { return law_repr(y); });
  copyable(yeoh);
  py::class_<Ogden> ogden(
      m,
      "Ogden",
      "Ogden law W/G = sum mu_p/alpha_p (l1^alpha_p + l2^alpha_p + l3^alpha_p - 3), 1 to 3\n"
      "terms, mu holding mu_p / G (sum mu_p alpha_p = 2; each mu_p alpha_p > 0,\n"
      "|alpha_p| >= 1).  Material.ogden(mu_mpa, alpha) takes the MPa values.");
  ogden
      .def(py::init([](std::vector<double> mu, std::vector<double> alpha) {
             return Ogden{std::move(mu), std::move(alpha)};
           }),
           py::arg("mu") = Ogden{}.mu,
           py::arg("alpha") = Ogden{}.alpha)
      .def_readwrite("mu", &Ogden::mu, "mu_p / G (a copy: assign a new list to change it)")
      .def_readwrite("alpha", &Ogden::alpha, "exponents alpha_p")
      .def("__repr__", [](const Ogden& o) { return law_repr(o); });
  copyable(ogden);
  py::class_<ArrudaBoyce> arruda_boyce(
      m,
      "ArrudaBoyce",
      "Arruda-Boyce eight-chain law with N Kuhn segments per chain (> 1), scaled to the\n"
      "initial shear modulus G; locks at I1 = 3 N (chain stretch sqrt(N))");
  arruda_boyce
      .def(py::init([](double n) { return ArrudaBoyce{n}; }), py::arg("n") = ArrudaBoyce{}.n)
      .def_static(
          "from_chain_stretch",
          [](double chain_stretch) { return ArrudaBoyce{chain_stretch * chain_stretch}; },
          py::arg("chain_stretch"),
          "the law whose chains lock at stretch sqrt(N) = chain_stretch")
      .def_readwrite("n", &ArrudaBoyce::n, "Kuhn segments per chain N")
      .def_property_readonly("chain_stretch", &ArrudaBoyce::chain_stretch, "sqrt(N)")
      .def("__repr__", [](const ArrudaBoyce& a) { return law_repr(a); });
  copyable(arruda_boyce);
  py::class_<GentGent> gent_gent(
      m,
      "GentGent",
      "Gent-Gent law (Pucci & Saccomandi 2002) W/G = -(1 - beta)(J_lim/2) ln(1 - (I1 - 3)/J_lim)\n"
      "+ (3 beta/2) ln(I2/3), beta = 2 C2 / (3 G) in [0, 1); beta = 0 is Gent");
  gent_gent
      .def(py::init([](double j_lim, double beta) {
             return GentGent{j_lim, beta};
           }),
           py::arg("j_lim") = GentGent{}.j_lim,
           py::arg("beta") = GentGent{}.beta)
      .def_readwrite("j_lim", &GentGent::j_lim, "limiting value of I1 - 3")
      .def_readwrite("beta", &GentGent::beta, "share of G in the ln(I2/3) term")
      .def("__repr__", [](const GentGent& g) { return law_repr(g); });
  copyable(gent_gent);

  py::class_<Material> material(m, "Material", "Shear modulus [MPa] and strain-energy law");
  material
      .def(py::init([](double g, const MaterialLaw& law) {
             return Material{g, law};
           }),
           py::arg("shear_modulus_mpa") = Material{}.shear_modulus_mpa,
           py::arg("law") = Gent{})
      .def_static(
          "gent",
          [](double g, double j_lim) {
            return Material{g, Gent{j_lim}};
          },
          py::arg("shear_modulus_mpa") = Material{}.shear_modulus_mpa,
          py::arg("j_lim") = Gent{}.j_lim,
          "Gent rubber (the paper's law)")
      .def_static(
          "neo_hookean",
          [](double g) {
            return Material{g, NeoHookean{}};
          },
          py::arg("shear_modulus_mpa") = Material{}.shear_modulus_mpa,
          "neo-Hookean rubber")
      .def_static(
          "mooney_rivlin",
          [](double g, double alpha) {
            return Material{g, MooneyRivlin{alpha}};
          },
          py::arg("shear_modulus_mpa") = Material{}.shear_modulus_mpa,
          py::arg("alpha") = MooneyRivlin{}.alpha,
          "Mooney-Rivlin rubber, alpha = C2 / (C1 + C2)")
      .def_static(
          "yeoh",
          [](double c10, double c20, double c30) {
            if (!std::isfinite(c10) || c10 <= 0.0)
              throw py::value_error(fmt::format(
                  "c10_mpa: Yeoh C10 must be a finite number > 0 MPa (G = 2 C10), got {}", c10));
            const double g = 2.0 * c10;
            return Material{g, Yeoh{c20 / g, c30 / g}};
          },
          py::arg("c10_mpa"),
          py::arg("c20_mpa") = 0.0,
          py::arg("c30_mpa") = 0.0,
          "Yeoh rubber from C10, C20, C30 [MPa]: G = 2 C10")
      .def_static(
          "ogden",
          [](const std::vector<double>& mu_mpa, const std::vector<double>& alpha) {
            return raising_value_error([&] { return ogden_material(mu_mpa, alpha); });
          },
          py::arg("mu_mpa"),
          py::arg("alpha"),
          "Ogden rubber from mu_p [MPa] and alpha_p (1 to 3 terms): G = sum mu_p alpha_p / 2")
      .def_readwrite(
          "shear_modulus_mpa", &Material::shear_modulus_mpa, "initial shear modulus G [MPa]")
      .def_property(
          "law",
          [](const Material& mat) { return mat.law; },
          [](Material& mat, const MaterialLaw& law) { mat.law = law; },
          "the strain-energy law (a copy: assign a new one to change it)")
      .def_property_readonly(
          "law_name", [](const Material& mat) { return law_name(mat.law); }, "e.g. 'gent'")
      .def_property_readonly(
          "j_lim",
          [](const Material& mat) -> py::object {
            if (const auto* g = std::get_if<Gent>(&mat.law)) return py::float_(g->j_lim);
            return py::none();
          },
          "J_lim for a Gent law, else None")
      .def_property_readonly(
          "alpha",
          [](const Material& mat) -> py::object {
            if (const auto* r = std::get_if<MooneyRivlin>(&mat.law)) return py::float_(r->alpha);
            return py::none();
          },
          "alpha for a Mooney-Rivlin law, else None")
      .def_property_readonly(
          "locking_first_invariant",
          [](const Material& mat) { return locking_first_invariant(mat.law); },
          "I1 at which the law locks: 3 + J_lim for Gent, inf otherwise")
      .def_property_readonly(
          "description", [](const Material& mat) { return describe(mat); }, "in words")
      .def("__repr__", &material_repr);
  copyable(material);
  def_elementwise(material,
                  "uniaxial_stress_mpa",
                  &uniaxial_mpa,
                  "stretch",
                  "Nominal stress [MPa] in uniaxial tension at the given stretch");
  def_elementwise(material,
                  "equibiaxial_stress_mpa",
                  &equibiaxial_mpa,
                  "stretch",
                  "Nominal stress [MPa] in equibiaxial tension (as under the tip)");
  def_elementwise(material,
                  "radial_stress_mpa",
                  &radial_mpa,
                  "Membrane nominal stress s1 [MPa] along lambda1 at stretches lambda1, lambda2");
  def_elementwise(material,
                  "hoop_stress_mpa",
                  &hoop_mpa,
                  "Membrane nominal stress s2 [MPa] along lambda2 at stretches lambda1, lambda2");

  constexpr const char* i1_doc =
      "I1 = lambda1^2 + lambda2^2 + 1/(lambda1 lambda2)^2 of an incompressible membrane";
  m.def("first_invariant",
        &first_invariant_of,
        py::arg("lambda1").noconvert(),
        py::arg("lambda2").noconvert(),
        i1_doc);
  m.def(
      "first_invariant",
      [](const Stretches& l1, const Stretches& l2) {
        return as_array(py::vectorize(&first_invariant_of)(l1, l2));
      },
      py::arg("lambda1"),
      py::arg("lambda2"));

  py::class_<StickCriterion> stick(
      m,
      "StickCriterion",
      "When the membrane, held at the indenter's edge at first, starts to slide.  Also given as\n"
      "the CLI's --stick text: 'none', 'always', 'coulomb', 'force:<N>', 'depth:<mm>', "
      "'edge-tension:<N/mm>'.");
  stick
      .def(py::init([](StickRule rule, double threshold) {
             return StickCriterion{rule, threshold};
           }),
           py::arg("rule") = StickRule::None,
           py::arg("threshold") = 0.0)
      .def(py::init([](const std::string& text) { return stick_of(text); }), py::arg("text"))
      .def_static("none",
                  [] {
                    return StickCriterion{StickRule::None, 0.0};
                  })
      .def_static("always",
                  [] {
                    return StickCriterion{StickRule::Always, 0.0};
                  })
      .def_static("coulomb",
                  [] {
                    return StickCriterion{StickRule::Coulomb, 0.0};
                  })
      .def_static(
          "force",
          [](double n) {
            return StickCriterion{StickRule::Force, n};
          },
          py::arg("force_n"))
      .def_static(
          "depth",
          [](double mm) {
            return StickCriterion{StickRule::Depth, mm};
          },
          py::arg("depth_mm"))
      .def_static(
          "edge_tension",
          [](double n_per_mm) {
            return StickCriterion{StickRule::EdgeTension, n_per_mm};
          },
          py::arg("tension_n_per_mm"))
      .def_readwrite("rule", &StickCriterion::rule)
      .def_readwrite("threshold",
                     &StickCriterion::threshold,
                     "threshold of the rule: N (force), mm (depth), N/mm (edge tension)")
      .def("__repr__", &stick_repr);
  copyable(stick);

  const Problem defaults;
  py::class_<Problem> problem(
      m,
      "Problem",
      "The membrane, the indenter, the contact and the failure criterion; defaults are the\n"
      "paper's lubricated silicone membrane and 2 mm indenter.");
  problem
      .def(py::init([](const Geometry& g,
                       const Indenter& indenter,
                       const Material& mat,
                       double friction,
                       double critical_i1,
                       const std::variant<StickCriterion, std::string>& stick,
                       const std::variant<PartTwoEquation, std::string>& equation,
                       const Preload& preload,
                       const std::vector<FailureCriterion>& criteria) {
             Problem p;
             p.geometry = g;
             p.preload = preload;
             p.indenter = indenter;
             p.material = mat;
             p.friction = friction;
             p.critical_i1 = critical_i1;
             p.criteria = criteria;
             p.stick = stick_of(stick);
             p.part_two_equation = part_two_equation_of(equation);
             return p;
           }),
           py::arg("geometry") = defaults.geometry,
           py::arg("indenter") = defaults.indenter,
           py::arg("material") = defaults.material,
           py::arg("friction") = defaults.friction,
           py::arg("critical_i1") = defaults.critical_i1,
           py::arg("stick") = defaults.stick,
           py::arg("part_two_equation") = defaults.part_two_equation,
           py::arg("preload") = defaults.preload,
           py::arg("criteria") = std::vector<FailureCriterion>{})
      .def_readwrite("geometry", &Problem::geometry)
      .def_readwrite("preload", &Problem::preload, "the pre-stretch before indentation (Preload)")
      .def_readwrite(
          "indenter", &Problem::indenter, "the probe (FlatPunch, SphereTipped, Ball or Cone)")
      .def_readwrite("material", &Problem::material)
      .def_readwrite(
          "friction", &Problem::friction, "Coulomb coefficient mu' (0.18 lubricated, 1.95 dry)")
      .def_readwrite("critical_i1", &Problem::critical_i1, "I1 at which the membrane punctures")
      .def_readwrite("criteria",
                     &Problem::criteria,
                     "failure criteria (CriticalFirstInvariant, MaxPrincipalStretch,\n"
                     "CriticalEnergyDensity, CriticalTrueStress, CriticalEnergyRelease);\n"
                     "empty: critical_i1 alone, else the first met governs")
      .def_property(
          "stick",
          [](Problem& p) -> StickCriterion& { return p.stick; },
          [](Problem& p, const std::variant<StickCriterion, std::string>& s) {
            p.stick = stick_of(s);
          },
          py::return_value_policy::reference_internal,
          "stick -> slip rule (StickCriterion, or its CLI text such as 'force:0.3')")
      .def_property(
          "part_two_equation",
          [](const Problem& p) { return p.part_two_equation; },
          [](Problem& p, const std::variant<PartTwoEquation, std::string>& e) {
            p.part_two_equation = part_two_equation_of(e);
          },
          "PartTwoEquation, or 'ring-balance' / 'paper-eq18'")
      .def_property_readonly(
          "force_scale_n", &force_scale_n, "2 pi G H A [N]: normalised force = F / this")
      .def_property_readonly("reference_clamp_radius_mm",
                             &reference_clamp_radius_mm,
                             "A / L0 [mm]: the radius of the stress-free disc that is clamped")
      .def("validation_errors",
           py::overload_cast<const Problem&>(&validation_errors),
           "Every problem with the input (ValidationError: attribute and message); empty if valid")
      .def(
          "validate",
          [](const Problem& p) {
            if (const auto message = invalid_input_message(p); !message.empty())
              throw py::value_error(message);
          },
          "Raise ValueError listing every invalid parameter")
      .def("__repr__", [](const Problem& p) {
        return fmt::format(
            "Problem(geometry={}, indenter={}, material={}, friction={:g}, critical_i1={:g}, "
            "stick={}, part_two_equation='{}', preload={})",
            geometry_repr(p.geometry),
            indenter_repr(p.indenter),
            material_repr(p.material),
            p.friction,
            p.critical_i1,
            stick_repr(p.stick),
            to_string(p.part_two_equation),
            preload_repr(p.preload));
      });
  copyable(problem);

  py::class_<SolverOptions> options(m, "SolverOptions", "Tolerances and limits of the solver");
  options.def(py::init<>())
      .def_readwrite("integration_rel_tol", &SolverOptions::integration_rel_tol)
      .def_readwrite("integration_abs_tol", &SolverOptions::integration_abs_tol)
      .def_readwrite("shooting_tol", &SolverOptions::shooting_tol)
      .def_readwrite("curve_tol", &SolverOptions::curve_tol)
      .def_readwrite("field_points", &SolverOptions::field_points)
      .def_readwrite("max_shooting_iterations", &SolverOptions::max_shooting_iterations)
      .def_readwrite("max_steps", &SolverOptions::max_steps)
      .def_readwrite("record_fields", &SolverOptions::record_fields)
      .def_readwrite("energy_to_puncture",
                     &SolverOptions::energy_to_puncture,
                     "fill PuncturePrediction.energy_to_puncture_mj (costs about a third of a "
                     "200-point curve)")
      .def_readwrite("failure_verdict",
                     &SolverOptions::failure_verdict,
                     "fill PuncturePrediction.failure_verdict for a pre-tensioned membrane "
                     "(follows the 200-point loading curve)")
      .def_readwrite("puncture_top_stretch_start",
                     &SolverOptions::puncture_top_stretch_start,
                     "a warm start: a neighbouring problem's PuncturePrediction."
                     "part_two_top_stretch, or None (cold); the puncture then agrees with the "
                     "cold one to the shooting's tolerance, not bit for bit")
      .def("__repr__", [](const SolverOptions& s) {
        return fmt::format(
            "SolverOptions(integration_rel_tol={:g}, integration_abs_tol={:g}, shooting_tol={:g}, "
            "curve_tol={:g}, field_points={}, max_shooting_iterations={}, max_steps={}, "
            "record_fields={}, energy_to_puncture={}, failure_verdict={})",
            s.integration_rel_tol,
            s.integration_abs_tol,
            s.shooting_tol,
            s.curve_tol,
            s.field_points,
            s.max_shooting_iterations,
            s.max_steps,
            s.record_fields,
            s.energy_to_puncture,
            s.failure_verdict);
      });
  copyable(options);
}

}  // namespace puncture::python
