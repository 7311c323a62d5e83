#pragma once
// The discrete problem: the parts of the meridian, each a chain of elements whose nodal values
// and end radii are either unknowns or prescribed by the contact configuration; the assembly of
// the total energy, its gradient, its sparse Hessian and the indenter's reaction.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "fe/element_energy.hpp"
#include "puncture/membrane_fields.hpp"

namespace puncture::fe {

// A nodal value or end radius: an unknown of the discrete problem plus a prescribed offset, or
// (index -1) a value the contact configuration prescribes.
struct Slot {
  int index = -1;         // position in the vector of unknowns; -1 when prescribed
  double value = 0.0;     // the prescribed value, or the offset added to the unknown
  bool at_depth = false;  // a deflection prescribed equal to the depth: its reaction is the force
};

inline Slot unknown_slot(int index, double offset = 0.0) { return Slot{index, offset, false}; }
inline Slot fixed_slot(double value, bool at_depth = false) { return Slot{-1, value, at_depth}; }

struct MeshPart {
  MembranePart part = MembranePart::Free;
  bool logarithmic = false;
  int elements = 0;
  Slot start, end;         // reference radii of the part's ends
  std::vector<Slot> r, z;  // per node: elements * order + 1
  // Set for a part lying on a smooth probe: r then holds the arclength along its profile.
  const RigidProfile* profile = nullptr;
};

struct Mesh {
  int order = 2;
  int unknowns = 0;
  double pressure = 0.0;        // P = p (A / L0) / (G H): the energy minimised is U - p V
  std::vector<MeshPart> parts;  // from the centre outward
};

inline double value_of(const Slot& slot, const Eigen::VectorXd& x) {
  return slot.index >= 0 ? x[slot.index] + slot.value : slot.value;
}

// The local values, slots and place of element `e` of `part`.
inline ElementPlace gather(const Mesh& mesh, const MeshPart& part, int e, const Eigen::VectorXd& x,
                           std::array<double, kMaxLocal>& values,
                           std::array<const Slot*, kMaxLocal>& slots) {
  const int p = mesh.order;
  values.fill(0.0);
  slots.fill(nullptr);
  for (int i = 0; i <= p; ++i) {
    slots[local_r(i)] = &part.r[e * p + i];
    slots[local_z(p, i)] = &part.z[e * p + i];
  }
  slots[local_start_radius(p)] = &part.start;
  slots[local_end_radius(p)] = &part.end;
  for (int k = 0; k < local_size(p); ++k) values[k] = value_of(*slots[k], x);
  return ElementPlace{p,
                      part.logarithmic,
                      double(e) / part.elements,
                      1.0 / part.elements,
                      part.profile,
                      part.profile ? 0.0 : mesh.pressure};
}

// Raises `largest_i1` and its reference radius [mm] (`clamp_mm` scales the mesh's lengths / A) to
// the largest I1 of `part`, looked for at both ends and the quadrature points of every element.
inline void raise_largest_first_invariant(const Mesh& mesh, const MeshPart& part,
                                          const Eigen::VectorXd& x, double clamp_mm,
                                          double& largest_i1, double& at_reference_radius_mm) {
  static const std::array<double, 7> sample_points = [] {
    std::array<double, 7> etas{-1.0, 1.0};
    for (std::size_t k = 0; k < gauss_points().size(); ++k) etas[k + 2] = gauss_points()[k].first;
    return etas;
  }();
  std::array<double, kMaxLocal> values;
  std::array<const Slot*, kMaxLocal> slots;
  for (int e = 0; e < part.elements; ++e) {
    const ElementPlace place = gather(mesh, part, e, x, values, slots);
    for (double eta : sample_points) {
      double l1, l2, radius, weight;
      if (!stretches_at(place, values, eta, l1, l2, radius, weight)) continue;
      const double i1 = first_invariant(l1, l2);
      if (i1 > largest_i1) {
        largest_i1 = i1;
        at_reference_radius_mm = radius * clamp_mm;
      }
    }
  }
}

struct Assembly {
  bool admissible = true;
  double energy = 0.0;  // integral of W / G  R dR over the membrane, lengths / A (less P V / 2 pi)
  Eigen::VectorXd gradient;  // with respect to the unknowns
  Eigen::SparseMatrix<double> hessian;
  double reaction = 0.0;  // d energy / d depth: the normalised force F / (2 pi G H A)
};

inline double total_energy(const MaterialLaw& law, const Mesh& mesh, const Eigen::VectorXd& x) {
  double energy = 0.0;
  std::array<double, kMaxLocal> values;
  std::array<const Slot*, kMaxLocal> slots;
  for (const MeshPart& part : mesh.parts)
    for (int e = 0; e < part.elements; ++e) {
      const ElementPlace place = gather(mesh, part, e, x, values, slots);
      energy += element_energy_value(law, place, values);
      if (!std::isfinite(energy)) return energy;
    }
  return energy;
}

// The integral of z r dr over the parts off a probe's profile (lengths / A): -V / (2 pi A^3) of
// their share of the volume between the membrane and the clamp plane, by the elements' Gauss rule
// (exact: the integrand is a polynomial).
inline double free_volume_integral(const Mesh& mesh, const Eigen::VectorXd& x) {
  double sum = 0.0;
  std::array<double, kMaxLocal> values;
  std::array<const Slot*, kMaxLocal> slots;
  for (const MeshPart& part : mesh.parts)
    if (!part.profile)
      for (int e = 0; e < part.elements; ++e) {
        const ElementPlace place = gather(mesh, part, e, x, values, slots);
        for (const auto& [eta, w_gauss] : gauss_points())
          sum += volume_integrand(place, values, eta) * w_gauss;
      }
  return sum;
}

inline Assembly assemble(const MaterialLaw& law, const Mesh& mesh, const Eigen::VectorXd& x) {
  Assembly a;
  a.gradient = Eigen::VectorXd::Zero(mesh.unknowns);
  std::vector<Eigen::Triplet<double>> triplets;
  std::array<double, kMaxLocal> values;
  std::array<const Slot*, kMaxLocal> slots;
  const int size = local_size(mesh.order);
  for (const MeshPart& part : mesh.parts)
    for (int e = 0; e < part.elements; ++e) {
      const ElementPlace place = gather(mesh, part, e, x, values, slots);
      const ElementResult element = element_energy(law, place, values);
      if (!element.admissible) {
        a.admissible = false;
        a.energy = std::numeric_limits<double>::infinity();
        return a;
      }
      a.energy += element.energy;
      for (int k = 0; k < size; ++k) {
        if (slots[k]->at_depth) a.reaction += element.gradient[k];
        const int row = slots[k]->index;
        if (row < 0) continue;
        a.gradient[row] += element.gradient[k];
        for (int j = 0; j < size; ++j)
          if (slots[j]->index >= 0)
            triplets.emplace_back(row, slots[j]->index, element.hessian(k, j));
      }
    }
  a.hessian.resize(mesh.unknowns, mesh.unknowns);
  a.hessian.setFromTriplets(triplets.begin(), triplets.end());
  return a;
}

}  // namespace puncture::fe
