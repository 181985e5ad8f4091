// Shell patches, seams and meshes as bytes (pack.hpp), field by field: the structs hold vectors and
// maps, and their padding must not travel.
#include "patch/pack.hpp"

namespace boltnet {
namespace {

template <class V> void PutMap(PackWriter &w, const std::map<std::string, V> &m)
{
  w.Put((std::uint64_t)m.size());
  for (const auto &[k, v] : m) {
    w.Put(k);
    w.Put(v);
  }
}

template <class V> void GetMap(PackReader &r, std::map<std::string, V> &m)
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

void Put(PackWriter &w, const ElementGeometry &g)
{
  w.Put(g.n);
  w.Put(g.X);
  w.Put(g.V);
  w.Put(g.directors);
}

void Get(PackReader &r, ElementGeometry &g)
{
  r.Get(g.n);
  r.Get(g.X);
  r.Get(g.V);
  r.Get(g.directors);
}

} // namespace

void Pack(PackWriter &w, const ShellMesh &m)
{
  w.Put(m.x);
  w.Put(m.elems);
  PutMap(w, m.node_sets);
  w.Put(m.directors);
}

void Unpack(PackReader &r, ShellMesh &m)
{
  r.Get(m.x);
  r.Get(m.elems);
  GetMap(r, m.node_sets);
  r.Get(m.directors);
}

void Pack(PackWriter &w, const ShellPatch &p)
{
  w.Put(p.id);
  Pack(w, p.mesh);
  w.Put(p.material);
  w.Put(p.drill);
  w.Put((std::uint64_t)p.shared.size());
  for (const auto &s : p.shared) {
    Put(w, s.geom);
    w.Put(s.node);
    w.Put(s.elem);
    w.Put(s.part_node);
  }
  w.Put((std::uint64_t)p.joint_nodes.size());
  for (const auto &jn : p.joint_nodes) {
    w.Put(jn.x);
    w.Put(jn.axis);
    w.Put(jn.footprint);
  }
  PutMap(w, p.part_set_size);
  w.Put(p.part_node);
  w.Put(p.part_elem);
  w.Put(p.condensed);
  w.Put(p.carried);
}

void Unpack(PackReader &r, ShellPatch &p)
{
  std::uint64_t n;
  r.Get(p.id);
  Unpack(r, p.mesh);
  r.Get(p.material);
  r.Get(p.drill);
  r.Get(n);
  p.shared.resize(n);
  for (auto &s : p.shared) {
    Get(r, s.geom);
    r.Get(s.node);
    r.Get(s.elem);
    r.Get(s.part_node);
  }
  r.Get(n);
  p.joint_nodes.resize(n);
  for (auto &jn : p.joint_nodes) {
    r.Get(jn.x);
    r.Get(jn.axis);
    r.Get(jn.footprint);
  }
  GetMap(r, p.part_set_size);
  r.Get(p.part_node);
  r.Get(p.part_elem);
  r.Get(p.condensed);
  r.Get(p.carried);
  p.carried_index.clear();
  for (size_t i = 0; i < p.carried.size(); ++i) p.carried_index[p.carried[i]] = (int)i;
}

void Pack(PackWriter &w, const Seam &s)
{
  w.Put(s.part);
  w.Put(s.va);
  w.Put(s.vb);
  w.Put(s.material);
  w.Put(s.drill);
  w.Put((std::uint64_t)s.elems.size());
  for (const auto &e : s.elems) {
    Put(w, e.geom);
    w.Put(e.side);
    w.Put(e.node);
  }
}

void Unpack(PackReader &r, Seam &s)
{
  std::uint64_t n;
  r.Get(s.part);
  r.Get(s.va);
  r.Get(s.vb);
  r.Get(s.material);
  r.Get(s.drill);
  r.Get(n);
  s.elems.resize(n);
  for (auto &e : s.elems) {
    Get(r, e.geom);
    r.Get(e.side);
    r.Get(e.node);
  }
}

} // namespace boltnet
