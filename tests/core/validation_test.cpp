#include "softtune/validation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

using namespace softtune;

namespace {
TuneRequest valid() {
  TuneRequest r;
  r.response_frames = 12;
  r.oscillation = Oscillation::some;
  r.effective_mass = 1.0;
  return r;
}
Constraint2D valid_constraint() {
  Constraint2D c;
  c.body_a.is_static = true;
  c.body_b.mass = 1.0;
  c.body_b.inertia = 0.1;
  c.anchor_b = {0.5, 0.0};
  c.axis = {0, 1};
  return c;
}
std::string field_of(const std::function<void(TuneRequest&)>& change) {
  TuneRequest r = valid();
  change(r);
  auto e = validate_tune_request(r);
  return e ? e->field : "ok";
}
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

TEST(Validation, AcceptsTheDefaultRequest) { EXPECT_EQ(field_of([](TuneRequest&) {}), "ok"); }

TEST(Validation, NamesEachBadField) {
  EXPECT_EQ(field_of([](TuneRequest& r) { r.fps = 0; }), "fps");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.fps = kNan; }), "fps");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.fps = kInf; }), "fps");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.substeps = 0; }), "substeps");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.substeps = 5000; }), "substeps");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.fps = 100000; r.substeps = 100; }), "substeps");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.response_frames = 0; }), "response_frames");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.response_frames = -12; }), "response_frames");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.response_frames = kNan; }), "response_frames");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.basis_fps = -60; }), "basis_fps");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.frequency_hz = 5; }), "response_frames");  // both given
  EXPECT_EQ(field_of([](TuneRequest& r) { r.response_frames.reset(); }), "response_frames");  // neither
  EXPECT_EQ(field_of([](TuneRequest& r) { r.response_frames.reset(); r.frequency_hz = -1; }), "frequency_hz");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.response_frames.reset(); r.frequency_hz = 2e6; }), "frequency_hz");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.damping_ratio = 0.5; }), "oscillation");  // both given
  EXPECT_EQ(field_of([](TuneRequest& r) { r.oscillation.reset(); }), "oscillation");  // neither
  EXPECT_EQ(field_of([](TuneRequest& r) { r.oscillation.reset(); r.damping_ratio = -0.1; }), "damping_ratio");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.oscillation.reset(); r.damping_ratio = kInf; }), "damping_ratio");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.effective_mass = -1; }), "effective_mass");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.effective_mass = 0; }), "effective_mass");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.effective_mass = kNan; }), "effective_mass");
  EXPECT_EQ(field_of([](TuneRequest& r) { r.effective_mass.reset(); }), "effective_mass");  // neither
  EXPECT_EQ(field_of([](TuneRequest& r) { r.constraint = valid_constraint(); }), "effective_mass");  // both
}

TEST(Validation, NamesEachBadConstraintField) {
  auto with = [](const std::function<void(Constraint2D&)>& change) {
    return field_of([&](TuneRequest& r) {
      r.effective_mass.reset();
      Constraint2D c = valid_constraint();
      change(c);
      r.constraint = c;
    });
  };
  EXPECT_EQ(with([](Constraint2D&) {}), "ok");
  EXPECT_EQ(with([](Constraint2D& c) { c.body_b.mass = -1; }), "constraint.body_b.mass");
  EXPECT_EQ(with([](Constraint2D& c) { c.body_b.inertia = 0; }), "constraint.body_b.inertia");
  EXPECT_EQ(with([](Constraint2D& c) { c.body_b.position = {kNan, 0}; }), "constraint.body_b.position");
  EXPECT_EQ(with([](Constraint2D& c) { c.anchor_a = {1e9, 0}; }), "constraint.anchor_a");
  EXPECT_EQ(with([](Constraint2D& c) { c.axis = {0, 0}; }), "constraint.axis");
  EXPECT_EQ(with([](Constraint2D& c) { c.body_b.is_static = true; }), "constraint.body_b");
  EXPECT_EQ(with([](Constraint2D& c) { c.type = ConstraintType::angular; c.body_b.inertia.reset(); }), "constraint");
}

TEST(Validation, ThreeDimensionalInertiaMustBeATensor) {
  auto with = [](const Eigen::Matrix3d& inertia) {
    return field_of([&](TuneRequest& r) {
      r.effective_mass.reset();
      Constraint3D c;
      c.body_a.is_static = true;
      c.body_b.inertia = inertia;
      r.constraint = c;
    });
  };
  EXPECT_EQ(with(Eigen::Matrix3d::Identity()), "ok");
  Eigen::Matrix3d asym = Eigen::Matrix3d::Identity();
  asym(0, 1) = 0.5;
  EXPECT_EQ(with(asym), "constraint.body_b.inertia");
  EXPECT_EQ(with(-Eigen::Matrix3d::Identity()), "constraint.body_b.inertia");
}
