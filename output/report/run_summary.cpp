#include "output/report/run_summary.h"

#include <limits>
#include <type_traits>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace sled::report {
namespace {

using Json = nlohmann::json;

// Reads the members of one JSON object into fields; the first member of the wrong type is
// remembered as the error. A missing member leaves the field as it was; a null (sled writes a
// number that is not finite as null) makes a floating-point field NaN, shown as "–".
class MemberReader {
 public:
  MemberReader(const Json& object, std::string path, std::string* error)
      : object_(object), path_(std::move(path)), error_(error) {}

  template <typename T>
  void Number(const char* key, T& out) {
    if constexpr (std::is_floating_point_v<T>) {
      const auto at = object_.find(key);
      if (at != object_.end() && at->is_null()) out = std::numeric_limits<T>::quiet_NaN();
    }
    if (const Json* value = Find(key)) {
      if (value->is_number()) {
        out = value->get<T>();
      } else {
        Fail(key, "a number");
      }
    }
  }
  void OptionalNumber(const char* key, std::optional<double>& out) {
    if (const Json* value = Find(key)) {
      if (value->is_number()) {
        out = value->get<double>();
      } else {
        Fail(key, "a number or null");
      }
    }
  }
  void Text(const char* key, std::string& out) {
    if (const Json* value = Find(key)) {
      if (value->is_string()) {
        out = value->get<std::string>();
      } else {
        Fail(key, "a string");
      }
    }
  }
  void OptionalBool(const char* key, std::optional<bool>& out) {
    if (const Json* value = Find(key)) {
      if (value->is_boolean()) {
        out = value->get<bool>();
      } else {
        Fail(key, "true, false or null");
      }
    }
  }
  // The member if it is an object, else nullptr (an error when it is there but no object).
  const Json* Object(const char* key) {
    const Json* value = Find(key);
    if (value != nullptr && !value->is_object()) {
      Fail(key, "an object");
      return nullptr;
    }
    return value;
  }
  const Json* Array(const char* key) {
    const Json* value = Find(key);
    if (value != nullptr && !value->is_array()) {
      Fail(key, "an array");
      return nullptr;
    }
    return value;
  }
  std::string Path(const char* key) const { return path_.empty() ? key : path_ + "." + key; }
  bool failed() const { return !error_->empty(); }

 private:
  const Json* Find(const char* key) const {
    const auto at = object_.find(key);
    if (at == object_.end() || at->is_null()) return nullptr;
    return &*at;
  }
  void Fail(const char* key, const char* expected) {
    if (error_->empty()) *error_ = fmt::format("`{}` should be {}", Path(key), expected);
  }

  const Json& object_;
  std::string path_;
  std::string* error_;
};

void ReadIntegrator(const Json& object, std::string* error, IntegratorSummary& out) {
  MemberReader in(object, "integrator", error);
  in.Text("method", out.method);
  in.Number("relative_tolerance", out.relative_tolerance);
  in.Number("absolute_tolerance", out.absolute_tolerance);
  in.Number("steps", out.steps);
  in.Number("rejected_steps", out.rejected_steps);
  in.Number("evaluations", out.evaluations);
  in.Number("jacobians", out.jacobians);
  in.Number("factorizations", out.factorizations);
  in.Number("events", out.events);
  in.Number("decaying_steps", out.decaying_steps);
  in.Number("max_local_error", out.max_local_error);
  in.OptionalNumber("error_estimate", out.error_estimate);
}

EnergySummary ReadEnergy(const Json& object, std::string* error) {
  EnergySummary out;
  MemberReader in(object, "energy_balance", error);
  in.Number("kinetic", out.kinetic);
  in.Number("potential", out.potential);
  in.Number("absorbed", out.absorbed);
  in.Number("prescribed_work", out.prescribed_work);
  in.Number("applied_work", out.applied_work);
  in.Number("impulses", out.impulses);
  in.Number("residual", out.residual);
  in.Number("largest_residual", out.largest_residual);
  in.Number("scale", out.scale);
  in.Number("relative_residual", out.relative_residual);
  return out;
}

FailureSummary ReadFailure(const Json& object, std::string* error) {
  FailureSummary out;
  MemberReader in(object, "failure", error);
  in.Number("time", out.time);
  in.Text("where", out.where);
  in.Text("cause", out.cause);
  in.Text("source", out.source);
  return out;
}

CriterionSummary ReadCriterion(const Json& object, std::size_t index, std::string* error) {
  CriterionSummary out;
  MemberReader in(object, fmt::format("criteria[{}]", index), error);
  in.Text("name", out.name);
  in.Text("variant", out.variant);
  in.Text("target", out.target);
  in.OptionalNumber("value", out.value);
  in.Text("unit", out.unit);
  in.OptionalNumber("window_start", out.window_start);
  in.OptionalNumber("window_end", out.window_end);
  in.Number("filter_class", out.filter_class);
  in.OptionalNumber("limit", out.limit);
  in.Text("limit_source", out.limit_source);
  in.OptionalBool("pass", out.pass);
  in.Text("verdict", out.verdict);
  in.OptionalNumber("seen_from", out.seen_from);
  in.OptionalNumber("seen_until", out.seen_until);
  in.Text("reason", out.reason);
  return out;
}

PeakSummary ReadPeak(const Json& object, std::size_t index, std::string* error) {
  PeakSummary out;
  MemberReader in(object, fmt::format("peaks[{}]", index), error);
  in.Text("channel", out.channel);
  in.Number("value", out.value);
  in.Number("time", out.time);
  std::optional<bool> filtered;
  in.OptionalBool("filtered", filtered);
  out.filtered = filtered.value_or(false);
  return out;
}

}  // namespace

std::optional<RunSummaryFile> ParseRunSummary(const std::string& text, std::string* error) {
  std::string problem;
  const Json root = Json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded() || !root.is_object()) {
    if (error) *error = "summary.json is no JSON object";
    return std::nullopt;
  }
  RunSummaryFile out;
  MemberReader in(root, "", &problem);
  in.Text("scenario", out.scenario);
  in.Text("status", out.status);
  in.Number("start_time", out.start_time);
  in.Number("end_time", out.end_time);
  in.Number("stopped_at", out.stopped_at);
  in.Number("output_every", out.output_every);
  in.Number("rows", out.rows);
  in.Number("channels", out.channels);
  in.Number("wall_time_seconds", out.wall_time_seconds);
  if (const Json* integrator = in.Object("integrator")) {
    ReadIntegrator(*integrator, &problem, out.integrator);
  }
  if (const Json* energy = in.Object("energy_balance")) {
    out.energy_balance = ReadEnergy(*energy, &problem);
  }
  if (const Json* failure = in.Object("failure")) out.failure = ReadFailure(*failure, &problem);
  if (const Json* criteria = in.Array("criteria")) {
    for (std::size_t i = 0; i < criteria->size(); ++i) {
      const Json& item = (*criteria)[i];
      if (!item.is_object()) {
        if (problem.empty()) problem = fmt::format("`criteria[{}]` should be an object", i);
        continue;
      }
      out.criteria.push_back(ReadCriterion(item, i, &problem));
    }
  }
  if (const Json* peaks = in.Array("peaks")) {
    for (std::size_t i = 0; i < peaks->size(); ++i) {
      const Json& item = (*peaks)[i];
      if (!item.is_object()) {
        if (problem.empty()) problem = fmt::format("`peaks[{}]` should be an object", i);
        continue;
      }
      out.peaks.push_back(ReadPeak(item, i, &problem));
    }
  }
  if (const Json* warnings = in.Array("warnings")) {
    for (const Json& item : *warnings) {
      if (item.is_string()) {
        out.warnings.push_back(item.get<std::string>());
      } else if (problem.empty()) {
        problem = "`warnings` should hold strings";
      }
    }
  }
  if (!problem.empty()) {
    if (error) *error = "summary.json: " + problem;
    return std::nullopt;
  }
  return out;
}

}  // namespace sled::report
