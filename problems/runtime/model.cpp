// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/runtime/model.h"

#include <ceres/cost_function.h>
#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/sphere_manifold.h>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <unordered_map>

#include "core/solver_options.h"
#include "energies/registry.h"
#include "geometry/curves.h"
#include "mesh/elements.h"
#include "geometry/reference.h"
#include "mesh/similarity.h"
#include "analysis/smoothness_metrics.h"
#include "mesh/topology.h"
#include "problems/runtime/measures.h"
#include "problems/spec/selection.h"

namespace archgeo {
namespace {

// Displacement guard (core/problem.h Stage::guard_key): starts at this
// fraction of the bound, with this anchor weight, growing by this factor
// per round; a clamped vertex goes just inside the bound, so that rounding
// in the conversion back to file units cannot put it outside.
constexpr double kGuardStart = 0.5;
constexpr double kGuardFirst = 1.0;
constexpr double kGuardGrowth = 10.0;
constexpr double kClampMargin = 0.999;

ceres::LossFunction* Robust(const std::string& type, double scale) {
  if (type == "huber") return new ceres::HuberLoss(scale);
  if (type == "soft_l1") return new ceres::SoftLOneLoss(scale);
  if (type == "cauchy") return new ceres::CauchyLoss(scale);
  if (type == "arctan") return new ceres::ArctanLoss(scale);
  if (type == "tolerant") return new ceres::TolerantLoss(scale, scale);
  return nullptr;  // "none"
}

// A cost function whose residuals and Jacobians are zero (the zeroed term of
// a mutation check, energies/registry.h ZeroedTerm).
class ZeroedCost : public ceres::CostFunction {
 public:
  explicit ZeroedCost(ceres::CostFunction* inner) : inner_(inner) {
    set_num_residuals(inner->num_residuals());
    *mutable_parameter_block_sizes() = inner->parameter_block_sizes();
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    if (!inner_->Evaluate(parameters, residuals, jacobians)) return false;
    std::fill(residuals, residuals + num_residuals(), 0.0);
    const auto& sizes = parameter_block_sizes();
    for (size_t i = 0; jacobians && i < sizes.size(); ++i) {
      if (jacobians[i]) std::fill(jacobians[i], jacobians[i] + sizes[i] * num_residuals(), 0.0);
    }
    return true;
  }

 private:
  std::unique_ptr<ceres::CostFunction> inner_;
};

}  // namespace

void HookContext::RecordChecks(bool wait) {
  size_t done = 0;
  for (; done < checks.size(); ++done) {
    std::future<std::function<void(HookContext&)>>& check = checks[done];
    if (!wait && check.wait_for(std::chrono::seconds(0)) != std::future_status::ready) break;
    check.get()(*this);
  }
  checks.erase(checks.begin(), checks.begin() + long(done));
}

void HookContext::SetElements(const std::string& name, ElementSet set) {
  CHECK(model) << "SetElements before the model exists";
  model->SetElements(name, std::move(set));
}

double HookContext::Measure(const std::string& name) {
  CHECK(model) << "Measure before the model exists";
  return model->Measure(name);
}

// A term's view of the model.
class MeshModel::View : public TermContext {
 public:
  View(MeshModel& model, const TermSpec& spec)
      : model_(model), name_(spec.name), zeroed_(name_ == ZeroedTerm()) {}

  void Prepare(Residuals* residuals, const std::string& loss, double loss_scale) {
    residuals_ = residuals;
    parts_.clear();
    loss_ = loss;
    loss_scale_ = loss_scale;
    shared_losses_.clear();
    last_loss_ = nullptr;
    batches_.clear();
    options_.clear();
  }

  int NumVertices() const override { return int(model_.store_.mesh().number_of_vertices()); }
  double* Position(int v) override { return PositionBlock(model_.store_.mesh(), VertexIndex(v)); }
  const double* Original(int v) const override { return &model_.original_[3 * size_t(v)]; }
  const double* Previous(int v) const override { return &model_.previous_[3 * size_t(v)]; }
  const double* VertexNormal(int v) const override { return &model_.normals_[3 * size_t(v)]; }
  bool Fixed(int v) const override { return model_.hooks_.fixed[v]; }
  double* Block(std::string_view name, int index) override {
    if (name != block_name_) {  // terms read runs of one block
      block_ = model_.store_.Find(name);
      block_name_ = name;
    }
    return model_.store_.At(block_, index);
  }
  const double* ProjectedPoint(int v) const override {
    CHECK(!model_.projected_point_.empty()) << name_ << ": no projection this round";
    return &model_.projected_point_[3 * size_t(v)];
  }
  const double* ProjectedDirection(int v) const override {
    CHECK(!model_.projected_direction_.empty()) << name_ << ": no projection this round";
    return &model_.projected_direction_[3 * size_t(v)];
  }
  bool OnBoundaryCurve(int v) const override {
    return !model_.on_curve_.empty() && model_.on_curve_[v];
  }
  const ElementSet& Elements(const std::string& name) override { return model_.Elements(name); }
  const GridShared& grid() const override { return model_.hooks_.grid; }
  const Settings& settings() const override { return *model_.hooks_.settings; }
  const std::string& term_name() const override { return name_; }

  void FromFile(FrameMap map, double* values, int width) const override {
    BlockToCanonical(map, model_.hooks_.frame, values, width);
  }

  const std::vector<Curve>& Curves(const std::string& option) override {
    if (const auto it = curves_.find(option); it != curves_.end()) return it->second;
    const Mesh& reference = model_.hooks_.reference ? model_.hooks_.reference->Triangles()
                                                    : model_.store_.mesh();
    const std::vector<Polyline> polylines = TermCurves(
        *model_.hooks_.settings, "terms." + name_ + "." + option, model_.hooks_.frame, reference);
    std::vector<Curve>& out = curves_[option];
    for (const Polyline& p : polylines) out.push_back({Coordinates(p), p.closed});
    return out;
  }

  void Add(ceres::CostFunction* cost, const std::vector<double*>& blocks, const char* part,
           double weight) override {
    CHECK(residuals_) << name_ << ": Add outside Build";
    if (!Variable(blocks.data(), int(blocks.size()))) {
      delete cost;
      return;
    }
    if (zeroed_) cost = new ZeroedCost(cost);
    const ceres::LossFunction* loss = Loss(weight);
    residuals_->Add(cost, loss, blocks.data(), int(blocks.size()), Part(part));
  }

  Batch* Keep(std::unique_ptr<Batch> batch) override {
    CHECK(residuals_) << name_ << ": Add outside Build";
    return residuals_->Own(std::move(batch));
  }

  void AddElement(const Batch& batch, int element, double* const* blocks, int count,
                  const char* part, double weight) override {
    if (!Variable(blocks, count)) return;
    if (zeroed_) {
      residuals_->Add(new ZeroedCost(new BatchElement(batch, element)), Loss(weight), blocks, count,
                      Part(part));
      return;
    }
    residuals_->Add(&batch, element, Loss(weight), blocks, count, Part(part));
  }

  void SetUnit(double* block) override { SetManifold(block, new ceres::SphereManifold<3>()); }

  void SetManifold(double* block, ceres::Manifold* manifold) override {
    // The zeroed term's manifolds go too (on_curve has no residual, only its
    // manifold).
    if (zeroed_) {
      delete manifold;
      return;
    }
    residuals_->SetManifold(block, manifold);
  }

 private:
  // Whether a residual over `blocks` can change (a residual whose every block
  // is constant is dropped).
  bool Variable(double* const* blocks, int count) const {
    for (int a = 0; a < count; ++a) {
      if (!model_.IsConstant(blocks[a])) return true;
    }
    return false;
  }
  // One weighted loss per weight in a round (the residuals own it once,
  // however many residuals share it): a term that adds two weights in turn,
  // as proximity with its point weight, shares two.
  const ceres::LossFunction* Loss(double weight) {
    const double w = weight >= 0 ? weight : this->weight;
    if (last_loss_ && w == last_weight_) return last_loss_;  // terms add runs of one weight
    const auto [it, added] = shared_losses_.try_emplace(w, nullptr);  // no node if there
    if (added) {
      it->second = residuals_->Own(
          new ceres::ScaledLoss(Robust(loss_, loss_scale_), w, ceres::TAKE_OWNERSHIP));
    }
    last_weight_ = w;
    return last_loss_ = it->second;
  }
  // `part` is a literal (or nullptr: the term's name), so the same address
  // names the same part.
  int Part(const char* part) {
    const char* key = part ? part : name_.c_str();
    for (const auto& [address, index] : parts_) {
      if (address == key) return index;  // terms may alternate parts element by element
    }
    return parts_.emplace_back(key, residuals_->Part(key)).second;
  }

  MeshModel& model_;
  std::string name_;
  bool zeroed_;  // the term of a mutation check (ZeroedTerm)
  std::map<std::string, std::vector<Curve>> curves_;  // per option, read once per solve
  Residuals* residuals_ = nullptr;
  std::vector<std::pair<const char*, int>> parts_;  // this round's parts by key address
  std::string block_name_;  // the last Block's name and position in the store
  size_t block_ = 0;
  std::string loss_ = "none";
  double loss_scale_ = 1;
  std::unordered_map<double, const ceres::LossFunction*> shared_losses_;  // owned by residuals_
  double last_weight_ = 0;  // the last Loss, if any
  const ceres::LossFunction* last_loss_ = nullptr;
};

std::vector<const TermSpec*> TermsOf(const ProblemDecl& declaration) {
  std::vector<const TermSpec*> specs;
  for (const TermUse& use : declaration.terms) {
    const TermSpec* spec = FindTerm(use.term);
    CHECK(spec) << declaration.name << ": term '" << use.term << "' is not registered";
    specs.push_back(spec);
  }
  return specs;
}

MeshModel::MeshModel(const ProblemDecl& declaration, std::vector<const TermSpec*> terms,
                     HookContext& hooks)
    : declaration_(declaration), terms_(std::move(terms)), hooks_(hooks), store_(*hooks.store) {
  hooks_.model = this;
  const Mesh& mesh = store_.mesh();
  if (hooks_.fixed.size() != mesh.number_of_vertices()) hooks_.fixed.assign(mesh.number_of_vertices(), false);
  boundary_ = BoundaryVertices(mesh);
  for (const TermSpec* t : terms_) {
    views_[t->name] = std::make_unique<View>(*this, *t);
  }
  // Blocks: the declaration's, then those of every term (declared even when
  // the term is off: another term may read them).
  for (const BlockDecl& b : declaration_.blocks) store_.Declare(b);
  for (const TermSpec* t : terms_) {
    for (const BlockDecl& b : t->declares) store_.Declare(b);
  }
  Start();
}

void MeshModel::Restart() {
  // Every block back to zero, as declared on a new store: the inits set
  // what they set on a new model (some only a block still zero, e.g. the
  // plane normals two terms share).
  std::vector<double> state = store_.Save();
  std::fill(state.begin() + long(3 * store_.mesh().number_of_vertices()), state.end(), 0.0);
  store_.Restore(state);
  // Selections may read positions (problems/spec/selection.h): made anew.
  selected_.clear();
  subsets_.clear();
  StateChanged();
  Start();
}

void MeshModel::Rebase() {
  for (VertexIndex v : store_.mesh().vertices()) {
    const Point& p = store_.mesh().point(v);
    original_[3 * v.idx()] = p.x();
    original_[3 * v.idx() + 1] = p.y();
    original_[3 * v.idx() + 2] = p.z();
  }
}

void MeshModel::Start() {
  const Mesh& mesh = store_.mesh();
  const size_t n = mesh.number_of_vertices();
  box_diagonal_ = n > 0 ? PrincipalBoxDiagonal(mesh) : 0.0;
  start_ = mesh;
  original_.resize(3 * n);
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    original_[3 * v.idx()] = p.x();
    original_[3 * v.idx() + 1] = p.y();
    original_[3 * v.idx() + 2] = p.z();
  }
  previous_ = original_;
  ComputeVertexNormals();
  if (declaration_.init) declaration_.init(hooks_);
  for (const TermSpec* t : terms_) {
    if (!t->init) continue;
    View& view = *views_.at(t->name);
    view.elements = &Selected(*t);
    t->init(view);
  }
}

MeshModel::~MeshModel() {
  if (hooks_.model == this) hooks_.model = nullptr;
}

bool MeshModel::IsConstant(const double* block) const {
  const Mesh& mesh = store_.mesh();
  if (!mesh.is_empty()) {
    const double* first = &mesh.point(VertexIndex(0)).x();
    const size_t n = mesh.number_of_vertices();
    if (block >= first && block < first + 3 * n) {
      return hooks_.fixed[size_t(block - first) / 3];
    }
  }
  const auto it = constant_blocks_.find(block);
  return it != constant_blocks_.end();
}

void MeshModel::ComputeVertexNormals() {
  const Mesh& mesh = store_.mesh();
  const std::vector<Vec3> face_normals = FaceNormals(mesh);
  normals_.assign(3 * mesh.number_of_vertices(), 0.0);
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v)) continue;
    const Vec3 n = VertexNormal(mesh, face_normals, v);
    for (int k = 0; k < 3; ++k) normals_[3 * v.idx() + k] = n[k];
  }
}

void MeshModel::BeginRound(bool project) {
  hooks_.RecordChecks(false);
  const Mesh& mesh = store_.mesh();
  const size_t n = mesh.number_of_vertices();
  previous_.resize(3 * n);
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    previous_[3 * v.idx()] = p.x();
    previous_[3 * v.idx() + 1] = p.y();
    previous_[3 * v.idx() + 2] = p.z();
  }
  ComputeVertexNormals();
  projected_point_.clear();
  projected_direction_.clear();
  on_curve_.clear();
  if (!project || !hooks_.reference) return;
  // Boundary vertices go to the reference's boundary curve when the
  // boundary_proximity term is on and the reference has a boundary;
  // otherwise every vertex goes to the surface.
  const Settings& s = *hooks_.settings;
  const bool curves = hooks_.reference->HasBoundary() && s.schema().Find("terms.boundary_proximity.weight") &&
                      s.Number("terms.boundary_proximity.weight") > 0;
  projected_point_.resize(3 * n);
  projected_direction_.resize(3 * n);
  on_curve_.assign(n, 0);
  // Every vertex's closest point is independent (CGAL's trees answer
  // concurrent queries).
  const FullTeams teams;
#pragma omp parallel for schedule(dynamic, 1024)
  for (long i = 0; i < long(n); ++i) {
    const VertexIndex v{VertexIndex::size_type(i)};
    const Vec3 x = ToVec3(mesh.point(v));
    Vec3 point, direction;
    if (curves && boundary_[v.idx()]) {
      const auto c = hooks_.reference->ClosestOnBoundary(x);
      point = c->point;
      direction = c->tangent;
      on_curve_[v.idx()] = 1;
    } else {
      const auto c = hooks_.reference->Closest(x);
      point = c.point;
      direction = c.normal;
    }
    for (int k = 0; k < 3; ++k) {
      projected_point_[3 * v.idx() + k] = point[k];
      projected_direction_[3 * v.idx() + k] = direction[k];
    }
  }
}

void MeshModel::SetConstant(const std::string& block, int index) {
  constant_elements_.insert(store_.At(block, index));
}

void MeshModel::SetManifold(const std::string& block, int index,
                            std::function<ceres::Manifold*()> make) {
  manifolds_[store_.At(block, index)] = std::move(make);
}

void MeshModel::SetElements(const std::string& name, ElementSet set) {
  set.name = name;
  sets_[name] = std::move(set);
  selected_.clear();
  subsets_.clear();
}

const ElementSet& MeshModel::Elements(const std::string& name) {
  auto it = sets_.find(name);
  if (it == sets_.end()) {
    const std::vector<std::string>& names = ElementSetNames();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      throw hooks_.settings->Error(
          "problem", "no element set '" + name + "' in problem '" + declaration_.name + "'");
    }
    it = sets_.emplace(name, BuildElementSet(store_.mesh(), name)).first;
  }
  return it->second;
}

// `terms.<t>.select` (problems/spec/selection.h) on the set `terms.<t>.on`.
const ElementSet& MeshModel::Selected(const TermSpec& spec) {
  const std::string name = spec.name;
  if (const auto it = selected_.find(name); it != selected_.end()) return *it->second;
  const Settings& s = *hooks_.settings;
  const std::string on = s.String("terms." + name + ".on");
  const ElementSet& all = Elements(on);
  const std::string key = "terms." + name + ".select";
  const Selection selection = ParseSelection(s, key);
  if (selection.all()) return *selected_.emplace(name, &all).first->second;
  const std::vector<size_t> keep =
      SelectElements(selection, all, store_.mesh(), hooks_.fixed, hooks_.frame, s, key);
  const ElementSet& subset = subsets_[name] = all.Subset(keep);
  return *selected_.emplace(name, &subset).first->second;
}

void MeshModel::Build(const std::vector<ActiveTerm>& terms, int round, Residuals& residuals) {
  const Settings& s = *hooks_.settings;
  constant_blocks_ = constant_elements_;
  for (const std::string& name : store_.Names()) {
    if (!store_.Decl(name).constant) continue;
    const int n = store_.Count(name);
    for (int i = 0; i < n; ++i) constant_blocks_.insert(store_.At(name, i));
  }
  // Positions and element blocks are found by address (a speed hint).
  Mesh& mesh = store_.mesh();
  if (mesh.number_of_vertices() > 0) {
    residuals.AddressRange(PositionBlock(mesh, VertexIndex(0)), int(mesh.number_of_vertices()), 3);
  }
  for (const std::string& name : store_.Names()) {
    const int n = store_.Count(name), width = store_.Decl(name).width;
    const double* base = n > 0 ? store_.At(name, 0) : nullptr;
    if (base && store_.At(name, n - 1) == base + size_t(n - 1) * width) {
      residuals.AddressRange(base, n, width);
    }
  }
  for (const ActiveTerm& a : terms) {
    // The blocks a term reads are checked when it is active: a problem may
    // declare them in its init hook (global blocks), and a term no stage
    // activates needs none.
    for (const std::string& b : a.spec->reads) {
      CHECK(store_.Has(b)) << "term '" << a.spec->name << "' reads block '" << b
                           << "', which neither problem '" << declaration_.name
                           << "' nor its terms declare";
    }
    View& view = *views_.at(a.spec->name);
    view.elements = &Selected(*a.spec);
    view.weight = a.weight;
    view.band = a.spec->supports_band ? a.band : -1.0;
    view.round = round;
    const std::string prefix = "terms." + std::string(a.spec->name) + ".";
    view.Prepare(&residuals, s.String(prefix + "loss"), s.Number(prefix + "loss_scale"));
    if (a.spec->begin) a.spec->begin(view);
  }
  // Consecutive terms of one group on the same elements are added element by
  // element (the residual order of a vertex's proximity terms, say).
  for (size_t first = 0; first < terms.size();) {
    size_t last = first + 1;
    const TermSpec& head = *terms[first].spec;
    while (last < terms.size() && head.group[0] != '\0' &&
           std::string(terms[last].spec->group) == head.group &&
           views_.at(terms[last].spec->name)->elements->name ==
               views_.at(head.name)->elements->name) {
      ++last;
    }
    const ElementSet& elements = *views_.at(head.name)->elements;
    std::vector<std::pair<View*, const TermSpec*>> group;
    for (size_t t = first; t < last; ++t) {
      group.emplace_back(views_.at(terms[t].spec->name).get(), terms[t].spec);
    }
    for (size_t i = 0; i < elements.size(); ++i) {
      for (const auto& [view, spec] : group) spec->add(*view, i);
    }
    first = last;
  }
  for (const ActiveTerm& a : terms) {
    View& view = *views_.at(a.spec->name);
    if (a.spec->finish) a.spec->finish(view);
    view.Prepare(nullptr, "none", 1);
  }
  for (VertexIndex v : mesh.vertices()) {
    double* x = PositionBlock(mesh, v);
    if (hooks_.fixed[v.idx()] && residuals.Has(x)) residuals.SetConstant(x);
  }
  for (const double* b : constant_blocks_) {
    if (residuals.Has(b)) residuals.SetConstant(b);
  }
  for (const auto& [b, make] : manifolds_) {
    if (residuals.Has(b) && !constant_blocks_.count(b)) residuals.SetManifold(b, make());
  }
}

int MeshModel::Guard(double bound_relative) {
  Mesh& mesh = store_.mesh();
  const double bound = bound_relative * box_diagonal_;
  std::vector<bool> on_polygon(mesh.number_of_vertices(), false);
  for (FaceIndex f : mesh.faces()) {
    if (mesh.degree(f) <= 3) continue;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) on_polygon[v.idx()] = true;
  }
  int clamped = 0;
  for (VertexIndex v : mesh.vertices()) {
    const double* x0 = &original_[3 * v.idx()];
    const Point& p = mesh.point(v);
    const Vec3 d{p.x() - x0[0], p.y() - x0[1], p.z() - x0[2]};
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    CHECK(store_.Has("guard_weight")) << declaration_.name
                                      << ": a displacement guard needs the displacement_guard term";
    double* g = store_.At("guard_weight", int(v.idx()));
    if (length > kGuardStart * bound) *g = std::max(kGuardFirst, *g * kGuardGrowth);
    if (length > bound && !on_polygon[v.idx()]) {
      const double t = kClampMargin * bound / length;
      mesh.point(v) = Point(x0[0] + t * d[0], x0[1] + t * d[1], x0[2] + t * d[2]);
      ++clamped;
    }
  }
  return clamped;
}

double MeshModel::Measure(const std::string& name) {
  if (const auto it = cache_.find(name); it != cache_.end()) return it->second;
  if (const auto it = declaration_.measures.find(name); it != declaration_.measures.end()) {
    return cache_[name] = it->second(hooks_);
  }
  const MeasureGroup* group = FindMeasureGroup(name);
  CHECK(group) << "problem '" << declaration_.name << "': no measure '" << name << "'";
  for (const auto& [key, value] : (*group)(hooks_)) cache_[key] = value;
  CHECK(cache_.count(name)) << "measure group does not provide '" << name << "'";
  return cache_.at(name);
}

void MeshModel::StateChanged() {
  cache_.clear();
  ++hooks_.version;
}

std::vector<double> MeshModel::SaveState() const { return store_.Save(); }
void MeshModel::RestoreState(const std::vector<double>& state) { store_.Restore(state); }

double MeshModel::MaxMove(const std::vector<double>& a, const std::vector<double>& b) const {
  const size_t n = 3 * store_.mesh().number_of_vertices();
  double m = 0;
  for (size_t i = 0; i + 2 < n && i + 2 < a.size() && i + 2 < b.size(); i += 3) {
    const double dx = a[i] - b[i], dy = a[i + 1] - b[i + 1], dz = a[i + 2] - b[i + 2];
    m = std::max(m, std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  return m;
}

ValidityLimits LimitsOf(const Settings& s) {
  ValidityLimits l;
  l.max_reflex_degrees = s.Number("validity.max_reflex_degrees");
  l.max_flip_degrees = s.Number("validity.max_flip_degrees");
  l.min_edge_relative = s.Number("validity.min_edge_relative");
  l.max_crease_increase_degrees = s.Number("validity.max_crease_increase_degrees");
  l.min_corner_degrees = s.Number("validity.min_corner_degrees");
  l.max_aspect = s.Number("validity.max_aspect");
  l.self_intersections = s.Bool("validity.self_intersections");
  l.allow_input_defects = s.Bool("validity.allow_input_defects");
  return l;
}

// A round is judged on what the optimisation did: defects its input had
// too do not make it invalid (the final check judges them; run.cpp).
std::string MeshModel::Invalid() {
  if (!Finite()) return "finite: non-finite coordinates";
  ValidityLimits limits = LimitsOf(*hooks_.settings);
  limits.allow_input_defects = true;
  std::string reason = CheckValidity(store_.mesh(), &start_, limits, false).Reason();
  if (declaration_.invalid) reason += declaration_.invalid(hooks_);
  return reason;
}

// The variables: positions and the optimised blocks. Constant blocks are
// data and may hold NaN on purpose (hnet's frame_weights: no smooth join).
bool MeshModel::Finite() const {
  const Mesh& mesh = store_.mesh();
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) return false;
  }
  for (const std::string& name : store_.Names()) {
    const BlockDecl& decl = store_.Decl(name);
    if (decl.constant) continue;
    const size_t block = store_.Find(name);
    for (int i = 0, n = store_.Count(name); i < n; ++i) {
      const double* x = store_.At(block, i);
      for (int k = 0; k < decl.width; ++k) {
        if (!std::isfinite(x[k])) return false;
      }
    }
  }
  return true;
}

}  // namespace archgeo
