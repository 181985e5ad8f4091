// Shell patches, seams and meshes as bytes (pack.hpp), field by field: the structs hold vectors and
// maps, and their padding must not travel. Each type's fields are listed once, in Fields(), and
// walked by the writer and the reader alike, so the two cannot disagree on the order.
#include "patch/pack.hpp"

namespace boltnet {
namespace {

// The writer's and the reader's one step: a value (or a vector or string of them) out or in.
template <class T> void Field(PackWriter &w, const T &v) { w.Put(v); }
template <class T> void Field(PackReader &r, T &v) { r.Get(v); }

template <class V> void Field(PackWriter &w, const std::map<std::string, V> &m)
{
  w.Put((std::uint64_t)m.size());
  for (const auto &[k, v] : m) {
    w.Put(k);
    w.Put(v);
  }
}

template <class V> void Field(PackReader &r, std::map<std::string, V> &m)
{
  std::uint64_t n;
  r.Get(n);
  m.clear();
  for (std::uint64_t i = 0; i < n; ++i) {
    std::string k;
    r.Get(k);
    r.Get(m[k]);
  }
}

// A vector of structs: its length, then each element's fields (F: the element's Fields()).
template <class T, class F> void Elements(PackWriter &w, const std::vector<T> &v, F &&fields)
{
  w.Put((std::uint64_t)v.size());
  for (const T &e : v) fields(w, e);
}

template <class T, class F> void Elements(PackReader &r, std::vector<T> &v, F &&fields)
{
  std::uint64_t n;
  r.Get(n);
  v.clear();
  for (std::uint64_t i = 0; i < n; ++i) fields(r, v.emplace_back());
}

// The field lists. A is PackWriter (S const) or PackReader.
template <class A, class S> void GeometryFields(A &a, S &g)
{
  Field(a, g.n);
  Field(a, g.X);
  Field(a, g.V);
  Field(a, g.directors);
}

template <class A, class S> void MeshFields(A &a, S &m)
{
  Field(a, m.x);
  Field(a, m.elems);
  Field(a, m.node_sets);
  Field(a, m.directors);
}

template <class A, class S> void PatchFields(A &a, S &p)
{
  Field(a, p.id);
  MeshFields(a, p.mesh);
  Field(a, p.material);
  Field(a, p.drill);
  Elements(a, p.shared, [](A &b, auto &s) {
    GeometryFields(b, s.geom);
    Field(b, s.node);
    Field(b, s.elem);
    Field(b, s.part_node);
  });
  Field(a, p.shared_in_set);
  Elements(a, p.joint_nodes, [](A &b, auto &jn) {
    Field(b, jn.x);
    Field(b, jn.axis);
    Field(b, jn.footprint);
  });
  Field(a, p.part_set_size);
  Field(a, p.part_node);
  Field(a, p.part_elem);
  Field(a, p.condensed);
  Field(a, p.carried);
}

template <class A, class S> void SeamFields(A &a, S &s)
{
  Field(a, s.part);
  Field(a, s.va);
  Field(a, s.vb);
  Field(a, s.material);
  Field(a, s.drill);
  Elements(a, s.elems, [](A &b, auto &e) {
    GeometryFields(b, e.geom);
    Field(b, e.side);
    Field(b, e.node);
  });
}

} // namespace

void Pack(PackWriter &w, const ShellMesh &m) { MeshFields(w, m); }
void Unpack(PackReader &r, ShellMesh &m) { MeshFields(r, m); }

void Pack(PackWriter &w, const ShellPatch &p) { PatchFields(w, p); }

void Unpack(PackReader &r, ShellPatch &p)
{
  PatchFields(r, p);
  p.carried_index.clear();
  for (size_t i = 0; i < p.carried.size(); ++i) p.carried_index[p.carried[i]] = (int)i;
}

void Pack(PackWriter &w, const Seam &s) { SeamFields(w, s); }
void Unpack(PackReader &r, Seam &s) { SeamFields(r, s); }

} // namespace boltnet
