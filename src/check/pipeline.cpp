// nbscope check: one frame's lanes, faults and cross-check (pipeline.hpp).
#include "check/pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

#include "core/error.hpp"
#include "core/plugin_detector.hpp"

namespace nbscope {

namespace {
using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }
}  // namespace

Pipeline::Lane::Lane(std::string_view algorithm) : detector(make_lane_detector(algorithm)) {
  if (algorithm == kRecordedAlgorithm) recorded = static_cast<RecordedPairsDetector*>(detector.get());
}

Pipeline::Pipeline(const PipelineOptions& options) : options_(options), checker_(CheckOptions{options.brute_limit}) {
  lanes_.emplace_back(options_.algorithm);
  result_.lanes.front().algorithm = options_.algorithm;
  if (lanes_.front().recorded) check_recorded_fault(options_.fault);
}
Pipeline::~Pipeline() = default;

void Pipeline::set_algorithm(std::string_view name, const std::function<void()>& accept_recorded) {
  Lane fresh(name);
  if (fresh.recorded && accept_recorded) accept_recorded();  // refused here, not on the next frame
  lanes_.front() = std::move(fresh);
  LaneResult& lane = result_.lanes.front();  // its report stays until the next run
  lane.algorithm = std::string(name);
  lane.pairs.clear();
  lane.grid = Grid{};
  lane.cells.clear();
  options_.algorithm = std::string(name);
}

void Pipeline::set_comparison_algorithms(const std::vector<std::string>& names, const std::function<void()>& accept_recorded) {
  std::vector<Lane> fresh;
  for (const std::string& name : names) {
    fresh.emplace_back(name);
    if (fresh.back().recorded && accept_recorded) accept_recorded();
  }
  lanes_.erase(lanes_.begin() + 1, lanes_.end());
  result_.lanes.resize(1);
  for (std::size_t k = 0; k < names.size(); ++k) {
    lanes_.push_back(std::move(fresh[k]));
    result_.lanes.emplace_back().algorithm = names[k];
  }
  comparison_names_ = names;
}

bool Pipeline::has_recorded_lane() const {
  return std::any_of(lanes_.begin(), lanes_.end(), [](const Lane& l) { return l.recorded != nullptr; });
}

void Pipeline::remember_previous(std::int64_t frame, Elements previous) {
  stale_ = std::move(previous);
  stale_for_ = frame;
}

void Pipeline::set_physics_ms(double ms) {
  for (LaneResult& lane : result_.lanes) lane.report.timings.physics_ms = ms;
}

void Pipeline::clear_reports() {
  for (LaneResult& lane : result_.lanes) lane.report = FrameReport{};
}

void Pipeline::detect(Lane& lane, LaneResult& out, const Elements& input, const std::string& where, bool traced) {
  try {
    const auto t0 = Clock::now();
    std::shared_ptr<const FrameTrace> trace;
    std::optional<Grid> fitted;  // the elements' own grid, fitted once for the trace and the lane
    if (traced) {
      fitted = make_grid(input, detect_options_.grid);
      trace = trace_frame(*lane.detector, input, detect_options_, detect_options_.frame, *fitted);
    }
    if (trace && trace->detected) {
      out.pairs = trace->pairs;  // the traced run is the frame's detection: the detector is called once
      result_.trace = std::move(trace);
    } else {
      lane.detector->detect(input, detect_options_, out.pairs);  // too large to record: untraced (the trace is made on request)
    }
    sort_pairs(out.pairs);
    const Grid* own = lane.detector->last_grid();
    out.grid = own != nullptr ? *own : fitted ? *fitted : make_grid(input, detect_options_.grid);
    integerise_cells(input, out.grid, out.cells);
    lane.grid_cells.clear();
    if (const std::vector<CellIndex>* own = lane.detector->own_cells()) {
      // A plugin's own integerisation becomes the lane's cells (AABB-in-cells, the Violations panel);
      // the grid's are kept for the cells check.
      lane.grid_cells.swap(out.cells);
      out.cells = *own;
    }
    apply_output_fault(options_.fault, out.grid, out.cells, out.pairs);
    out.report.timings.detection_ms = ms_since(t0);
  } catch (const PluginError&) {
    throw;  // already names the library, the plugin and the frame
  } catch (const Error& e) {
    throw Error(where + out.algorithm + ": " + e.what());
  }
}

const FrameResult& Pipeline::run(const FrameInput& in) {
  const Frame& source = *in.source;
  const Elements& now = source.elements();
  const std::int64_t frame = source.frame();
  detected_on_source_ = true;
  if (options_.fault == Fault::StalePositions && !in.first) {
    // Last frame's positions; elements that did not exist then (emitted now) at their new ones.
    // A step leaves them remembered; a frame shown from the history fetches them only here, when asked.
    if (stale_for_ != frame) {
      stale_ = in.previous ? in.previous() : now;
      stale_for_ = frame;
    }
    detected_on_ = now;
    const Eigen::Index old_n = std::min(stale_.size(), now.size());
    detected_on_.x.head(old_n) = stale_.x.head(old_n);
    detected_on_.y.head(old_n) = stale_.y.head(old_n);
    detected_on_source_ = false;
  }
  const Elements& input = detector_input(source);
  detect_options_.frame = frame;  // for a plugin's messages
  detect_options_.check_walks = options_.checks;  // a plugin's lists, on the frames that are checked
  result_.trace.reset();  // made again on request, for this frame and detector
  result_.frame = frame;
  result_.time = source.time();
  result_.ids = source.ids();
  result_.columns = source.columns();
  for (std::size_t k = 0; k < lanes_.size(); ++k) {
    if (lanes_[k].recorded) lanes_[k].recorded->set_pairs(source.recorded_pairs());
    detect(lanes_[k], result_.lanes[k], input, in.where, k == 0 && record_traces_ && !lanes_[k].recorded);
  }

  if (!options_.checks) {
    for (LaneResult& lane : result_.lanes) {
      const double detection_ms = lane.report.timings.detection_ms, physics_ms = lane.report.timings.physics_ms;
      lane.report = FrameReport{};
      lane.report.frame = frame;
      lane.report.timings = {physics_ms, detection_ms, 0};
      lane.report.counts.elements = now.size();
      lane.report.counts.bodies = source.body_count();
      lane.report.counts.a = static_cast<std::int64_t>(lane.pairs.size());
    }
    result_.reference.clear();
    result_.box2d.clear();
    result_.touching.clear();
    result_.tight_aabb.clear();
  } else {
    // The first lane's check time includes the sets every lane shares (F, G, T).
    auto t0 = Clock::now();
    if (const Box2dFrame* box2d = source.box2d()) checker_.begin_frame(*box2d, detect_options_, lanes_.front().detector->name());  // R beside F, G, T
    else checker_.begin_frame(now, frame, detect_options_);
    for (std::size_t k = 0; k < lanes_.size(); ++k) {
      LaneResult& lane = result_.lanes[k];
      // The lane's contracts: along lane 0's trace when its one detection recorded it, else what the
      // detector itself said it did wrong.
      const auto c0 = Clock::now();
      std::optional<BrokenContract> contract;
      bool contract_checked = false;
      if (k == 0 && result_.trace && result_.trace->detected && result_.trace->refusal.empty()) {
        contract = first_broken_contract(*result_.trace);
        contract_checked = true;
      } else if (const Misbehaviour* m = lanes_[k].detector->misbehaviour()) {
        contract = api_rule_break(*m);
        contract_checked = true;
      }
      const double contract_ms = ms_since(c0);
      CheckInput check;
      check.contract_checked = contract_checked;
      check.contract = contract ? &*contract : nullptr;
      check.algorithm = lanes_[k].detector->name();
      check.pairs = &lane.pairs;
      check.cells = &lane.cells;
      check.grid_cells = lanes_[k].detector->own_cells() != nullptr ? &lanes_[k].grid_cells : nullptr;
      check.walks = lanes_[k].detector->walk_check();
      check.drop_box2d_contact = options_.fault == Fault::DropBox2dContact;
      check.recorded = lanes_[k].recorded != nullptr;
      if (check.recorded) check.precision = source.precision();
      checker_.check(check, lane.report);
      name_atoms(lane.report, result_.ids.get(), source.ranks());
      lane.report.check_timings.invariant_ms[static_cast<std::size_t>(Invariant::Contract)] += contract_ms;
      if (k == 0) result_.reference = checker_.reference_pairs();
      lane.report.timings.check_ms = ms_since(t0);
      t0 = Clock::now();
    }
    checker_.take_sets(result_.box2d, result_.touching, result_.tight_aabb);
  }
  result_.hash = hash_elements(now);
  for (LaneResult& lane : result_.lanes) lane.report.hash = result_.hash;
  return result_;
}

std::shared_ptr<const FrameTrace> Pipeline::trace(const Frame& source) {
  Lane& lane = lanes_.front();
  if (!result_.trace && lane.recorded) {
    // Read, not detected: nothing to step through, said in the panels' words.
    auto none = std::make_shared<FrameTrace>(refused_trace(source.frame(), lane.detector->name()));
    none->refusal = recorded_trace_refusal();
    result_.trace = std::move(none);
  }
  if (!result_.trace) {
    try {
      result_.trace = trace_frame(*lane.detector, detector_input(source), detect_options_, source.frame(), result_.selected().grid);
    } catch (const Error& e) {
      // The detection itself refused the frame (as a step would say): kept as the trace's reason, so
      // the panels show it and it is not tried again every UI frame.
      auto refused = std::make_shared<FrameTrace>(refused_trace(source.frame(), lane.detector->name()));
      refused->refusal = e.what();
      result_.trace = std::move(refused);
    }
  }
  return result_.trace;
}

}  // namespace nbscope
