// The messages between nbscope and a plugin's host process (plugin_wire.hpp).
#include "io/plugin_wire.hpp"

#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <unordered_map>

#include "core/error.hpp"
#include "core/plugin_detector.hpp"

namespace nbscope {

void WireWriter::raw(const void* data, std::size_t bytes) {
  if (bytes == 0) return;
  const auto* from = static_cast<const char*>(data);
  bytes_.insert(bytes_.end(), from, from + bytes);
}

std::string WireReader::text() {
  std::string s(count(1), '\0');
  raw(s.data(), s.size());
  return s;
}

void WireReader::raw(void* out, std::size_t bytes) {
  if (static_cast<std::size_t>(end_ - at_) < bytes) throw Error("plugin host: a message ended early");
  if (bytes != 0) std::memcpy(out, at_, bytes);
  at_ += bytes;
}

std::size_t WireReader::count(std::size_t each) {
  const auto n = value<std::uint64_t>();
  if (each != 0 && n > static_cast<std::uint64_t>(end_ - at_) / each) throw Error("plugin host: a message ended early");
  return static_cast<std::size_t>(n);
}

namespace {

void put_column(WireWriter& out, const Eigen::ArrayXd& column) { out.array(column.data(), static_cast<std::size_t>(column.size())); }

void get_column(WireReader& in, Eigen::ArrayXd& column) {
  const std::size_t n = in.count(sizeof(double));
  column.resize(static_cast<Eigen::Index>(n));
  in.raw(column.data(), n * sizeof(double));
}

template <class T>
void put_optional(WireWriter& out, const std::optional<T>& v) {
  out.value<std::uint8_t>(v ? 1 : 0);
  if (v) out.value(*v);
}

template <class T>
void get_optional(WireReader& in, std::optional<T>& v) {
  if (in.value<std::uint8_t>() != 0) v = in.value<T>();
}

void put_misbehaviour(WireWriter& out, const Misbehaviour& m) {
  out.text(m.text);
  out.value(m.subject);
  out.value(static_cast<std::uint64_t>(m.operations));
  out.value<std::uint8_t>(m.cut ? 1 : 0);
  out.value<std::uint8_t>(m.cycle ? 1 : 0);
  out.value(m.cell_element);
  out.value(m.cell_axis);
  out.text(m.where);
}

Misbehaviour get_misbehaviour(WireReader& in) {
  Misbehaviour m;
  m.text = in.text();
  m.subject = in.value<Pair>();
  m.operations = static_cast<std::size_t>(in.value<std::uint64_t>());
  m.cut = in.value<std::uint8_t>() != 0;
  m.cycle = in.value<std::uint8_t>() != 0;
  m.cell_element = in.value<std::int32_t>();
  m.cell_axis = in.value<int>();
  m.where = in.text();
  return m;
}

// The trace: its arrays, then its events with each label as an index into a table of texts.
void put_trace(WireWriter& out, const TraceLog& trace) {
  out.value(static_cast<std::uint64_t>(trace.arrays().size()));
  for (const TracedArray& a : trace.arrays()) {
    out.text(a.name);
    out.array(a.shape.data(), a.shape.size());
    out.array(a.initial.data(), a.initial.size());
  }
  std::unordered_map<const char*, std::uint32_t> ids;
  std::vector<const char*> labels;
  std::vector<std::uint32_t> label_of;
  label_of.reserve(trace.events().size());
  const char* last = nullptr;  // labels come in runs: one lookup a run
  std::uint32_t last_id = 0;
  for (const TraceEvent& e : trace.events()) {
    if (e.label != last || label_of.empty()) {
      const auto [at, added] = ids.try_emplace(e.label, static_cast<std::uint32_t>(labels.size()));
      if (added) labels.push_back(e.label);
      last = e.label;
      last_id = at->second;
    }
    label_of.push_back(last_id);
  }
  out.value(static_cast<std::uint64_t>(labels.size()));
  for (const char* label : labels) out.text(label != nullptr ? label : "");
  out.array(trace.events().data(), trace.events().size());  // the label pointers in it mean nothing there
  out.array(label_of.data(), label_of.size());
}

void get_trace(WireReader& in, TraceLog* trace, std::vector<TraceEvent>& events) {
  const std::size_t arrays = in.count(1);
  for (std::size_t k = 0; k < arrays; ++k) {
    std::string name = in.text();
    std::vector<std::int64_t> shape;
    std::vector<std::int32_t> initial;
    in.array(shape);
    in.array(initial);
    if (trace != nullptr) trace->declare_array(std::move(name), std::move(shape), initial);
  }
  std::vector<const char*> labels(in.count(1));
  for (const char*& label : labels) label = intern_plugin_label(in.text().c_str());
  in.array(events);
  const std::size_t count = in.count(sizeof(std::uint32_t));
  if (count != events.size()) throw Error("plugin host: a trace's labels and events disagree");
  for (TraceEvent& e : events) {
    const auto id = in.value<std::uint32_t>();
    if (id >= labels.size()) throw Error("plugin host: a trace event names no label");
    e.label = labels[id];
  }
  if (trace != nullptr) trace->append(events);
}

}  // namespace

void encode(const Elements& e, const DetectRequest& request, WireWriter& out) {
  out.value<std::int32_t>(e.dim);
  put_column(out, e.x);
  put_column(out, e.y);
  put_column(out, e.dim == 3 ? e.z : Eigen::ArrayXd());
  put_column(out, e.r);
  const DetectOptions& o = request.options;
  put_optional(out, o.grid.cell_size);
  put_optional(out, o.grid.origin);
  put_optional(out, o.grid.cells);
  out.value(static_cast<std::uint64_t>(o.max_pairs));
  out.value(o.frame);
  out.value(o.touching);
  out.value<std::uint8_t>(o.check_walks ? 1 : 0);
  out.value<std::uint8_t>(request.traced ? 1 : 0);
  out.value<std::uint8_t>(request.keep_tests ? 1 : 0);
  out.value(request.operation_limit);
}

DetectRequest decode_request(WireReader& in) {
  DetectRequest request;
  Elements& e = request.elements;
  e.dim = in.value<std::int32_t>();
  get_column(in, e.x);
  get_column(in, e.y);
  get_column(in, e.z);
  get_column(in, e.r);
  if (e.dim != 2 && e.dim != 3) throw Error("plugin host: a frame of dimension " + std::to_string(e.dim));
  if (e.y.size() != e.x.size() || e.r.size() != e.x.size() || (e.dim == 3 && e.z.size() != e.x.size()))
    throw Error("plugin host: a frame's columns differ in length");
  DetectOptions& o = request.options;
  get_optional(in, o.grid.cell_size);
  get_optional(in, o.grid.origin);
  get_optional(in, o.grid.cells);
  o.max_pairs = static_cast<std::size_t>(in.value<std::uint64_t>());
  o.frame = in.value<std::int64_t>();
  o.touching = in.value<Touching>();
  o.check_walks = in.value<std::uint8_t>() != 0;
  request.traced = in.value<std::uint8_t>() != 0;
  request.keep_tests = in.value<std::uint8_t>() != 0;
  request.operation_limit = in.value<std::int64_t>();
  return request;
}

void encode(const DetectReply& reply, const TraceLog* trace, WireWriter& out) {
  out.value(reply.error);
  out.text(reply.message);
  out.array(reply.pairs.data(), reply.pairs.size());
  out.value<std::uint8_t>(reply.has_cells ? 1 : 0);
  out.array(reply.cells.data(), reply.cells.size());
  out.value<std::uint8_t>(reply.walks_checked ? 1 : 0);
  out.array(reply.walks.first.data(), reply.walks.first.size());
  out.value(reply.walks.count);
  out.value<std::uint8_t>(reply.misbehaviour ? 1 : 0);
  if (reply.misbehaviour) put_misbehaviour(out, *reply.misbehaviour);
  out.value<std::uint8_t>(trace != nullptr ? 1 : 0);
  if (trace != nullptr) put_trace(out, *trace);
}

void decode_reply(WireReader& in, DetectReply& reply, TraceLog* trace, std::vector<TraceEvent>& events) {
  reply.error = in.value<WireError>();
  reply.message = in.text();
  in.array(reply.pairs);
  reply.has_cells = in.value<std::uint8_t>() != 0;
  in.array(reply.cells);
  reply.walks_checked = in.value<std::uint8_t>() != 0;
  in.array(reply.walks.first);
  reply.walks.count = in.value<std::int64_t>();
  reply.misbehaviour.reset();
  if (in.value<std::uint8_t>() != 0) reply.misbehaviour = get_misbehaviour(in);
  if (trace != nullptr) trace->reset();
  if (in.value<std::uint8_t>() != 0) get_trace(in, trace, events);
}

bool send_message(int fd, const std::vector<char>& bytes) {
  const std::uint64_t size = bytes.size();
  auto put = [fd](const char* data, std::size_t left) {
    while (left > 0) {
      const ssize_t wrote = ::send(fd, data, left, MSG_NOSIGNAL);
      if (wrote < 0 && errno == EINTR) continue;
      if (wrote <= 0) return false;
      data += wrote;
      left -= static_cast<std::size_t>(wrote);
    }
    return true;
  };
  return put(reinterpret_cast<const char*>(&size), sizeof size) && put(bytes.data(), bytes.size());
}

bool receive_message(int fd, std::vector<char>& bytes) {
  auto get = [fd](char* data, std::size_t left) {
    while (left > 0) {
      const ssize_t got = ::read(fd, data, left);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) return false;
      data += got;
      left -= static_cast<std::size_t>(got);
    }
    return true;
  };
  std::uint64_t size = 0;
  if (!get(reinterpret_cast<char*>(&size), sizeof size)) return false;
  bytes.resize(static_cast<std::size_t>(size));
  return get(bytes.data(), bytes.size());
}

}  // namespace nbscope
