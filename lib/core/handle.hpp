// Owned PETSc objects as move-only C++ values: the destructor calls XxxDestroy. boltnet keeps
// them only inside objects that are destroyed before PetscFinalize (the assembly), never in
// globals (docs/architecture.md, "Ownership").
#pragma once
#include <petscmat.h>

#include <utility>

namespace boltnet {

template <class T, PetscErrorCode (*Destroy)(T *)>
class Handle {
public:
  Handle() = default;
  explicit Handle(T obj) : obj_(obj) {}
  Handle(const Handle &)            = delete;
  Handle &operator=(const Handle &) = delete;
  Handle(Handle &&o) noexcept : obj_(std::exchange(o.obj_, nullptr)) {}
  Handle &operator=(Handle &&o) noexcept
  {
    if (this != &o) {
      reset();
      obj_ = std::exchange(o.obj_, nullptr);
    }
    return *this;
  }
  ~Handle() { reset(); }
  // Destroys the object now (errors in a destructor cannot be raised: PETSc prints them).
  void reset()
  {
    if (obj_) (void)Destroy(&obj_);
    obj_ = nullptr;
  }
  T  get() const { return obj_; }
  T *out()
  {
    reset();
    return &obj_;
  }
  explicit operator bool() const { return obj_ != nullptr; }

private:
  T obj_ = nullptr;
};

using MatHandle = Handle<Mat, MatDestroy>;
using VecHandle = Handle<Vec, VecDestroy>;
using ISHandle  = Handle<IS, ISDestroy>;

} // namespace boltnet
