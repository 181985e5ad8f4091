// PSHELL and PCOMP to lib/shell sections (section.hpp). Nastran's PSHELL resultants: membrane
// T [G1], bending (12I/T^3) T^3/12 [G2], transverse shear (TS/T) T [G3], with [Gi] the plane
// stress matrix of material MIDi in its own axes; PCOMP by classical lamination theory
// (shell::LaminateMaterial) about the plane Z0 below the bottom ply.
#include "nastran/section.hpp"

#include <cmath>
#include <sstream>

namespace boltnet::nastran {

namespace {

using shell::Mat2;
using shell::Mat3;

std::string Num(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

struct Plane {
  Mat3 g{};     // plane stress stiffness
  Mat2 shear{}; // transverse shear moduli (G13, G23); 0 where the material is rigid in shear
};

Plane PlaneStress(const Deck &d, int mid)
{
  Plane p;
  if (d.mat1_index.count(mid)) {
    const Mat1 &m = d.mat1s[d.mat1_index.at(mid)];
    const double c = m.e / (1 - m.nu * m.nu);
    p.g = {c, m.nu * c, 0, m.nu * c, c, 0, 0, 0, m.g};
    p.shear = {m.g, 0, 0, m.g};
  } else {
    const Mat8 &m = d.mat8s[d.mat8_index.at(mid)];
    const double nu21 = m.nu12 * m.e2 / m.e1, den = 1 - m.nu12 * nu21;
    p.g = {m.e1 / den, m.nu12 * m.e2 / den, 0, m.nu12 * m.e2 / den, m.e2 / den, 0, 0, 0, m.g12};
    p.shear = {m.g1z, 0, 0, m.g2z};
  }
  return p;
}

[[noreturn]] void Fail(const Deck &d, const Source &src, const std::string &card, const std::string &what)
{
  throw Error(d.Where(src) + ": " + card + ": " + what, d.files[src.file], src.line, card.substr(0, card.find(' ')), 0);
}

template <class M>
M Scaled(const M &m, double s)
{
  M r = m;
  for (double &x : r) x *= s;
  return r;
}

} // namespace

shell::ShellMaterial Offset(const shell::ShellMaterial &m, double d)
{
  shell::ShellMaterial r = m;
  for (int i = 0; i < 9; ++i) {
    r.B[i] = m.B[i] - d * m.A[i];
    r.D[i] = m.D[i] - 2 * d * m.B[i] + d * d * m.A[i];
  }
  return r;
}

shell::ShellMaterial SectionOf(const Deck &d, int pid, double t, std::vector<std::string> &notes)
{
  shell::ShellMaterial s;
  if (d.pshell_index.count(pid)) {
    const PShell &p = d.pshells[d.pshell_index.at(pid)];
    const std::string card = "PSHELL " + std::to_string(pid);
    if (std::isnan(t)) t = p.t;
    if (std::isnan(t)) Fail(d, p.src, card, "no thickness: T is blank and the element gives none");
    if (p.mid1 <= 0) Fail(d, p.src, card, "MID1 is blank (no membrane stiffness): boltnet's shell needs MID1 and MID2");
    if (p.mid2 == -1) Fail(d, p.src, card, "MID2 = -1 (plane strain) is not supported");
    if (p.mid2 <= 0) Fail(d, p.src, card, "MID2 is blank (membrane only): boltnet's shell needs bending stiffness (MID2)");
    if (p.mid4 > 0) Fail(d, p.src, card, "MID4 (membrane-bending coupling) is not supported");
    const Plane g1 = PlaneStress(d, p.mid1), g2 = PlaneStress(d, p.mid2);
    s.A = Scaled(g1.g, t);
    s.D = Scaled(g2.g, p.bending * t * t * t / 12);
    Mat2 g3 = p.mid3 > 0 ? PlaneStress(d, p.mid3).shear : g2.shear;
    if (p.mid3 <= 0)
      notes.push_back(d.Where(p.src) + ": " + card + ": MID3 is blank (Nastran: no transverse shear flexibility); boltnet's MITC4 shell uses MID2's shear modulus with TS/T = " + Num(p.shear));
    if (g3[0] == 0 || g3[3] == 0) {
      // MAT8 with G1Z/G2Z blank is rigid in transverse shear in Nastran.
      const double g12 = PlaneStress(d, p.mid3 > 0 ? p.mid3 : p.mid2).g[8];
      notes.push_back(d.Where(p.src) + ": " + card + ": transverse shear modulus blank (rigid in Nastran): G12 = " + Num(g12) + " is used");
      if (g3[0] == 0) g3[0] = g12;
      if (g3[3] == 0) g3[3] = g12;
    }
    s.H = Scaled(g3, p.shear * t);
    s.thickness = t;
    const Mat3 &A = s.A, &D = s.D;
    if (!(A[0] > 0 && A[4] > 0 && A[8] > 0 && A[0] * A[4] > A[1] * A[3] && D[0] > 0 && D[4] > 0 && D[8] > 0 && s.H[0] > 0 && s.H[3] > 0))
      Fail(d, p.src, card, "the section is not positive definite (a material with E = 0 or G = 0?)");
    return s;
  }
  if (!d.pcomp_index.count(pid)) throw Error("property " + std::to_string(pid) + " is not a PSHELL or PCOMP", "", 0, "", 0);
  const PComp &p = d.pcomps[d.pcomp_index.at(pid)];
  const std::string card = "PCOMP " + std::to_string(pid);
  if (p.lam != Lam::Blank && p.lam != Lam::Sym) Fail(d, p.src, card, "LAM options MEM, BEND, SMEAR and SMCORE are not supported (blank or SYM)");
  std::vector<shell::Ply> plies;
  bool rigid_shear = false;
  for (const Ply &q : p.Stack()) {
    shell::Ply ply{q.theta, q.t, 0, 0, 0, 0, 0, 0};
    if (d.mat1_index.count(q.mid)) {
      const Mat1 &m = d.mat1s[d.mat1_index.at(q.mid)];
      ply.E1 = ply.E2 = m.e;
      ply.nu12 = m.nu;
      ply.G12 = ply.G13 = ply.G23 = m.g;
    } else {
      const Mat8 &m = d.mat8s[d.mat8_index.at(q.mid)];
      ply.E1 = m.e1, ply.E2 = m.e2, ply.nu12 = m.nu12, ply.G12 = m.g12;
      ply.G13 = m.g1z > 0 ? m.g1z : m.g12;
      ply.G23 = m.g2z > 0 ? m.g2z : m.g12;
      rigid_shear = rigid_shear || m.g1z == 0 || m.g2z == 0;
    }
    plies.push_back(ply);
  }
  if (rigid_shear)
    notes.push_back(d.Where(p.src) + ": " + card + ": a MAT8 ply has G1Z or G2Z blank (rigid in transverse shear in Nastran): its G12 is used");
  try {
    s = shell::LaminateMaterial(plies);
  } catch (const std::invalid_argument &e) {
    Fail(d, p.src, card, e.what());
  }
  const double h = p.Thickness();
  if (std::abs(p.z0 + h / 2) > 1e-12 * h) s = Offset(s, -(p.z0 + h / 2));
  return s;
}

} // namespace boltnet::nastran
