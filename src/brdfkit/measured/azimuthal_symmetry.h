#pragma once
// The azimuthal symmetry of a BRDF given as a function, found by probing it: whether ρ is unchanged
// when both directions turn about the normal, and if not, which of the symmetries an RGL file may
// rely on it has (measured/rgl_writer.h: RglWriteOptions::symmetry). Used to choose how a source is
// written (isotropic or anisotropic, which share of the incidence azimuths).
#include "brdfkit/measured/rgl_writer.h"

namespace brdfkit {

enum class AzimuthalSymmetry {
  None,      // anisotropic, no symmetry assumed
  HalfTurn,  // ρ(R wi, R wo) = ρ(wi, wo) for R the half turn about the normal
  Mirrors,   // also for the mirrors about the x and y axes
  Isotropic  // for every rotation about the normal
};

// Compares ρ at 16 fixed direction pairs with ρ at their images (three rotations, the half turn,
// the two mirrors): equal to 10⁻⁶ relative, or both without a value. Probes, not a proof: a source
// whose asymmetry lies away from every probe passes.
AzimuthalSymmetry azimuthal_symmetry(const RglSource& rho);

// RglWriteOptions::symmetry for a source with this symmetry (4 for an isotropic one: every
// symmetry holds).
int rgl_symmetry(AzimuthalSymmetry s);

}  // namespace brdfkit
