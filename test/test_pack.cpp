// Shell patches, seams and meshes through bytes (lib/patch/pack.hpp): what comes back equals, field
// by field, what went in, whatever the field; a buffer cut short is refused, not read past its end.
#include "patch/pack.hpp"

#include <cstdio>
#include <cstdlib>

using namespace boltnet;

namespace {

int failures = 0;

void Expect(bool ok, const char *what)
{
  if (!ok) {
    std::printf("FAIL: %s\n", what);
    ++failures;
  }
}

// Every field set to something other than its default, so that a field left out of Pack or Unpack
// shows.
ShellMesh SampleMesh(double shift)
{
  ShellMesh m;
  m.x         = {{0.0 + shift, 0.0, 0.5}, {1.0, 0.25, 0.0}, {1.0, 1.0, -0.125}, {0.0, 1.0, 3.0}, {2.0, 0.5, 0.0}};
  m.elems     = {{0, 1, 2, 3}, {1, 4, 2, -1}};
  m.node_sets = {{"xmin", {0, 3}}, {"load", {4}}, {"", {}}};
  m.directors = {{0, 0, 1}, {0, 0.1, 0.99}, {0, 0, 0}, {0, 0, 1}, {0.2, 0, 0.98}};
  return m;
}

ElementGeometry SampleGeometry(int n, double s)
{
  ElementGeometry g;
  g.n = n;
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k) {
      g.X[a][k] = s + 10 * a + k;
      g.V[a][k] = -s + a - k;
    }
  g.directors = true;
  return g;
}

bool SameGeometry(const ElementGeometry &a, const ElementGeometry &b) { return a.n == b.n && a.X == b.X && a.V == b.V && a.directors == b.directors; }

bool SameMesh(const ShellMesh &a, const ShellMesh &b) { return a.x == b.x && a.elems == b.elems && a.node_sets == b.node_sets && a.directors == b.directors; }

bool SameMaterial(const shell::ShellMaterial &a, const shell::ShellMaterial &b) { return a.A == b.A && a.B == b.B && a.D == b.D && a.H == b.H && a.thickness == b.thickness && a.direction == b.direction; }

ShellPatch SamplePatch()
{
  ShellPatch p;
  p.id       = 42;
  p.mesh     = SampleMesh(0.5);
  p.material = shell::IsotropicMaterial(70000, 0.33, 2.5);
  p.material.B[1] = 7; // a coupling term, to see B travel
  p.material.direction = {0.6, 0.8, 0};
  p.drill = 0.03;
  p.shared.push_back({SampleGeometry(4, 1), {0, -1, 2, 3}, 17, {5, 6, 7, 8}});
  p.shared.push_back({SampleGeometry(3, 2), {-1, 1, 4, -1}, 18, {9, 10, 11, -1}});
  p.shared_in_set = {{"skin", {0, 1}}, {"xmin", {1}}};
  p.joint_nodes.push_back({{1, 2, 3}, {0, 0, 1}, {0, 1, 2}});
  p.joint_nodes.push_back({{4, 5, 6}, {0, 1, 0}, {}});
  p.part_set_size = {{"", 100}, {"xmin", 11}};
  p.part_node     = {3, 9, 27, 81, 243};
  p.part_elem     = {5, 8};
  p.condensed     = true;
  p.carried       = {1, 4, 5, 6};
  for (size_t i = 0; i < p.carried.size(); ++i) p.carried_index[p.carried[i]] = (int)i;
  return p;
}

Seam SampleSeam()
{
  Seam s;
  s.part     = 7;
  s.va       = 3;
  s.vb       = 5;
  s.material = shell::IsotropicMaterial(210000, 0.3, 1.2);
  s.drill    = 0.2;
  s.elems.push_back({SampleGeometry(4, 3), {0, 1, -1, 1}, {2, 3, -1, 4}});
  s.elems.push_back({SampleGeometry(3, 4), {1, 0, 0, -1}, {5, 6, 7, -1}});
  return s;
}

} // namespace

int main()
{
  // Several objects in one buffer, read back in order.
  const ShellPatch  p = SamplePatch();
  const Seam        s = SampleSeam();
  const ShellMesh   m = SampleMesh(-1);
  std::vector<char> buf;
  PackWriter        w(buf);
  Pack(w, p);
  Pack(w, s);
  Pack(w, m);

  ShellPatch q;
  Seam       t;
  ShellMesh  n;
  PackReader r(buf.data(), buf.size());
  Unpack(r, q);
  Unpack(r, t);
  Unpack(r, n);
  Expect(r.Done(), "the buffer is read to its end");

  Expect(q.id == p.id, "patch id");
  Expect(SameMesh(q.mesh, p.mesh), "patch mesh");
  Expect(SameMaterial(q.material, p.material), "patch material");
  Expect(q.drill == p.drill, "patch drill");
  Expect(q.shared.size() == p.shared.size(), "shared elements");
  for (size_t i = 0; i < p.shared.size() && i < q.shared.size(); ++i)
    Expect(SameGeometry(q.shared[i].geom, p.shared[i].geom) && q.shared[i].node == p.shared[i].node && q.shared[i].elem == p.shared[i].elem && q.shared[i].part_node == p.shared[i].part_node, "a shared element");
  Expect(q.shared_in_set == p.shared_in_set, "shared elements within node sets");
  Expect(q.joint_nodes.size() == p.joint_nodes.size(), "joint nodes");
  for (size_t i = 0; i < p.joint_nodes.size() && i < q.joint_nodes.size(); ++i)
    Expect(q.joint_nodes[i].x == p.joint_nodes[i].x && q.joint_nodes[i].axis == p.joint_nodes[i].axis && q.joint_nodes[i].footprint == p.joint_nodes[i].footprint, "a joint node");
  Expect(q.part_set_size == p.part_set_size, "part set sizes");
  Expect(q.part_node == p.part_node && q.part_elem == p.part_elem, "part numbering");
  Expect(q.condensed == p.condensed && q.carried == p.carried, "carried nodes");
  Expect(q.carried_index == p.carried_index, "carried index rebuilt");
  Expect(q.nnodes() == p.nnodes(), "node count");

  Expect(t.part == s.part && t.va == s.va && t.vb == s.vb && SameMaterial(t.material, s.material) && t.drill == s.drill, "seam record");
  Expect(t.elems.size() == s.elems.size(), "seam elements");
  for (size_t i = 0; i < s.elems.size() && i < t.elems.size(); ++i) Expect(SameGeometry(t.elems[i].geom, s.elems[i].geom) && t.elems[i].side == s.elems[i].side && t.elems[i].node == s.elems[i].node, "a seam element");
  Expect(SameMesh(n, m), "mesh");

  // Every cut short of the whole buffer is refused with an exception.
  int refused = 0, cuts = 0;
  for (size_t len = 0; len < buf.size(); len += 7, ++cuts) {
    try {
      PackReader rr(buf.data(), len);
      ShellPatch a;
      Seam       b;
      ShellMesh  c;
      Unpack(rr, a);
      Unpack(rr, b);
      Unpack(rr, c);
    } catch (const std::runtime_error &) {
      ++refused;
    }
  }
  Expect(refused == cuts, "a buffer cut short is refused");

  std::printf("test_pack: %s (%zu bytes, %d cuts refused)\n", failures ? "FAIL" : "PASS", buf.size(), refused);
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
