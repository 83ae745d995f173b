#include "scbt/app/eval_run.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <thread>

#include "scbt/app/eval_jobs.h"
#include "scbt/app/eval_outputs.h"
#include "scbt/io/printable.h"
#include "scbt/io/same_file.h"
#include "scbt/peers/polygon_tracker.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

bool valid_name(const std::string& name) {
  return !name.empty() && name.find_first_of(",\"\r\n/\\") == std::string::npos && name != "." &&
         name != "..";
}

// The results folders to score, each checked to hold a file for a selected sequence.
std::vector<std::pair<std::string, std::string>> checked_results(
    const EvalRunOptions& options, const std::vector<DatasetSequence>& selected) {
  std::vector<std::pair<std::string, std::string>> results;
  for (const std::string& spec : options.results) {
    results.push_back(parse_results_spec(spec));
    const std::string& dir = results.back().second;
    if (!fs::is_directory(dir)) {
      throw std::runtime_error("--results " + spec + ": '" + dir + "' is not a directory");
    }
    const bool any = std::any_of(selected.begin(), selected.end(), [&](const DatasetSequence& s) {
      return fs::exists(results_path(dir, s.name));
    });
    if (!any) {
      throw std::runtime_error("--results " + spec + ": no <Seq>.txt file for any selected " +
                               "sequence in '" + dir + "'");
    }
  }
  return results;
}

// Is `path` `folder` itself or inside it (both resolved: symlinks, "..")?
bool is_within(const fs::path& path, const fs::path& folder) {
  const fs::path p = fs::weakly_canonical(fs::absolute(path));
  const fs::path f = fs::weakly_canonical(fs::absolute(folder));
  auto pi = p.begin();
  for (auto fi = f.begin(); fi != f.end(); ++fi, ++pi) {
    if (fi->empty()) continue;  // a trailing separator
    if (pi == p.end() || *pi != *fi) return false;
  }
  return true;
}

// Refuses, before any work, an output folder inside the dataset and results written over the
// results or ground truth being scored (--results mine=OUT/bdsp --trackers bdsp --out OUT).
void check_eval_paths(const EvalRunOptions& options, const EvalRunContext& run) {
  if (is_within(options.out, options.dataset)) {
    throw std::invalid_argument("--out " + printable(options.out) + " is inside --dataset " +
                                printable(options.dataset) + "; refusing to write into it");
  }
  std::vector<NamedPath> inputs;
  std::vector<NamedPath> outputs;
  for (const EvalSequence& s : run.sequences) {
    inputs.push_back({"--dataset", s.files.ground_truth});
    for (const auto& [name, dir] : run.results) {
      inputs.push_back({"--results " + name + "=", results_path(dir, s.files.name)});
    }
    for (const std::string& tracker : run.trackers) {
      outputs.push_back(
          {"--out", results_path((fs::path(options.out) / tracker).string(), s.files.name)});
    }
  }
  // "--results NAME= PATH" reads oddly: the option and the path are joined.
  try {
    check_no_overwrite(inputs, outputs, {});
  } catch (const std::invalid_argument& e) {
    std::string message = e.what();
    const std::size_t joined = message.find("= ");
    if (joined != std::string::npos) message.erase(joined + 1, 1);
    throw std::invalid_argument(message);
  }
}

void log_start(const EvalRunContext& run, std::ostream& log) {
  long total_frames = 0;
  for (const EvalJob& job : run.jobs) total_frames += static_cast<long>(job.sequence->truth.size());
  log << "eval: " << run.jobs.size() << " jobs (" << join(run.trackers)
      << (run.trackers.empty() ? "" : " run")
      << (run.results.empty() ? ""
                              : std::string(run.trackers.empty() ? "" : "; ") + "scoring " +
                                    std::to_string(run.results.size()) + " results folders")
      << ") on " << run.sequences.size() << " sequences, " << total_frames << " frames, "
      << run.threads << " threads\n"
      << std::flush;
}

}  // namespace

std::pair<std::string, std::string> parse_results_spec(const std::string& spec) {
  const size_t eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size()) {
    throw std::invalid_argument("--results '" + spec + "': expected NAME=DIR");
  }
  std::string name = spec.substr(0, eq);
  if (!valid_name(name)) {
    throw std::invalid_argument("--results '" + spec + "': name '" + name +
                                "' must be non-empty without , \" / or \\");
  }
  return {name, spec.substr(eq + 1)};
}

void EvalRunOptions::check() const {
  if (dataset.empty()) throw std::invalid_argument("--dataset is required");
  if (out.empty()) throw std::invalid_argument("--out is required");
  if (jobs < 0) throw std::invalid_argument("--jobs " + std::to_string(jobs) + " must be >= 0");
  if (max_frames < 0) {
    throw std::invalid_argument("--max-frames " + std::to_string(max_frames) + " must be >= 0");
  }
  if (max_frames == 1) {
    throw std::invalid_argument("--max-frames 1 leaves nothing to track (use 0 for all frames)");
  }
  if (gap != GapVariantKind::kNone && perturbation.frame_stride() != 1) {
    throw std::invalid_argument("gap variants (--gaps) cannot be combined with a frame stride");
  }
  if (!(gap_position > 0.0 && gap_position < 1.0)) {
    throw std::invalid_argument("--gap-at " + std::to_string(gap_position) +
                                " must be in (0, 1) of the sequence");
  }
  const std::vector<std::string> known = polygon_tracker_names();
  std::set<std::string> names;
  std::set<std::string> trackers_run;
  for (const std::string& name : trackers) {
    const std::string canonical = canonical_polygon_tracker_name(name);
    if (std::find(known.begin(), known.end(), canonical) == known.end()) {
      throw std::invalid_argument("unknown tracker '" + name + "' (known: " + join(known) + ")");
    }
    if (!trackers_run.insert(canonical).second || !names.insert(name).second) {
      throw std::invalid_argument("tracker '" + canonical + "' given twice");
    }
  }
  for (const std::string& spec : results) {
    const std::string name = parse_results_spec(spec).first;
    if (!names.insert(name).second) {
      throw std::invalid_argument("--results name '" + name + "' is used twice");
    }
  }
  tracker.check();
}

EvalRunSummary run_eval(const EvalRunOptions& options, std::ostream& log) {
  const EvalClock::time_point start = EvalClock::now();
  options.check();
  EvalRunSummary summary;

  // Everything that can be checked is checked before any work starts.
  const std::vector<DatasetSequence> selected =
      select_dataset_sequences(options.dataset, options.sequences);
  EvalRunContext run;
  run.trackers = options.trackers;
  if (run.trackers.empty() && options.results.empty()) run.trackers = polygon_tracker_names();
  run.results = checked_results(options, selected);
  run.sequences.reserve(selected.size());
  for (const DatasetSequence& files : selected) {
    run.sequences.push_back({files, load_truth(files, options.max_frames)});
    // A gap that does not fit the sequence fails here, not in a job.
    sequence_gap(options, static_cast<int>(run.sequences.back().truth.size()));
  }
  for (const std::string& name : run.trackers) {
    for (const EvalSequence& s : run.sequences) run.jobs.push_back({name, "", &s});
  }
  for (const auto& [name, dir] : run.results) {
    for (const EvalSequence& s : run.sequences) run.jobs.push_back({name, dir, &s});
  }

  check_eval_paths(options, run);

  fs::create_directories(options.out);
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  run.threads = std::max(
      1, std::min(options.jobs > 0 ? options.jobs : hardware, static_cast<int>(run.jobs.size())));
  summary.jobs = static_cast<int>(run.jobs.size());
  summary.threads = run.threads;
  if (!options.quiet) log_start(run, log);
  run.outcomes = run_eval_jobs(run.jobs, options, run.threads, log);

  const std::vector<std::string> failures = write_eval_outputs(options, run, &summary, start);
  if (!options.quiet) {
    log << "eval: wrote " << join(summary.files) << " in " << std::fixed;
    log.precision(1);
    log << summary.seconds << " s\n" << std::defaultfloat << std::flush;
  }
  if (!failures.empty()) {
    throw std::runtime_error(std::to_string(failures.size()) + " of " +
                             std::to_string(summary.jobs) +
                             " jobs failed; first: " + failures.front());
  }
  return summary;
}

}  // namespace scbt
