#include "machine/transforms.h"

#include <cmath>

namespace gcx::machine {

namespace {
Vec3 normalOf(motion::Plane p) {
  switch (p) {
  case motion::Plane::XY:
    return Vec3::UnitZ();
  case motion::Plane::ZX:
    return Vec3::UnitY(); // Z toward X is positive about +Y
  case motion::Plane::YZ:
    return Vec3::UnitX();
  }
  return Vec3::UnitZ();
}
} // namespace

bool Transforms::has(Kind k) const {
  for (const Layer& l : layers_)
    if (l.kind == k) return true;
  return false;
}

std::optional<Transforms::Kind> Transforms::innermost() const {
  if (layers_.empty()) return std::nullopt;
  return layers_.back().kind;
}

void Transforms::rotate(motion::Plane plane, const Vec3& centre, double degrees) {
  cancel(Kind::Rotate);
  rotationDegrees_ = degrees;
  Affine m = Eigen::Translation3d(centre) *
             Eigen::AngleAxisd(degrees * M_PI / 180.0, normalOf(plane)) *
             Eigen::Translation3d(-centre);
  layers_.push_back({Kind::Rotate, m});
  rebuild();
}

void Transforms::scale(const Vec3& centre, const Vec3& factors) {
  cancel(Kind::Scale);
  Affine m = Eigen::Translation3d(centre) * Eigen::Scaling(factors) * Eigen::Translation3d(-centre);
  layers_.push_back({Kind::Scale, m});
  rebuild();
}

void Transforms::cancel(Kind k) {
  std::erase_if(layers_, [k](const Layer& l) { return l.kind == k; });
  if (k == Kind::Rotate) rotationDegrees_ = 0;
  rebuild();
}

void Transforms::mirror(unsigned mask, const Vec3& position) {
  for (int a = 0; a < 3; ++a)
    if (mask & (1u << a)) mirrorPosition_[a] = position[a];
  mirrorAxes_ |= mask;
  rebuild();
}

void Transforms::cancelMirror(unsigned mask) {
  mirrorAxes_ &= ~mask;
  rebuild();
}

void Transforms::clear() {
  layers_.clear();
  mirrorAxes_ = 0;
  rotationDegrees_ = 0;
  rebuild();
}

void Transforms::rebuild() {
  // P_out = Mirror(L_1(L_2(...L_n(P)))): the last activated layer acts first
  Affine t = Affine::Identity();
  if (mirrorAxes_) {
    Vec3 s(1, 1, 1);
    for (int a = 0; a < 3; ++a)
      if (mirrorAxes_ & (1u << a)) s[a] = -1;
    t = Eigen::Translation3d(mirrorPosition_) * Eigen::Scaling(s) *
        Eigen::Translation3d(-mirrorPosition_);
  }
  for (const Layer& l : layers_)
    t = t * l.m;
  total_ = t;
}

} // namespace gcx::machine
