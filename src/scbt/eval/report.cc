#include "scbt/eval/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace scbt {
namespace {

constexpr const char* kSummaryColumns[] = {
    "tracker",    "sequence", "frames",    "failures",    "success_5", "success_10",
    "success_20", "auc",      "mean_e_al", "median_e_al", "tracked",   "held",
    "edges",      "nodes",    "line_ms",   "grouping_ms", "track_ms",  "fps"};

std::string number(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.10g", value);
  return buffer;
}

void check_name(const std::string& name) {
  if (name.find_first_of(",\"\r\n") != std::string::npos) {
    throw std::invalid_argument("name '" + name +
                                "' cannot be written to CSV (has , \" or a line break)");
  }
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> fields;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
}

// Markdown cells.
std::string percent(double rate) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.1f%%", 100.0 * rate);
  return buffer;
}

std::string fixed(double value, int decimals) {
  if (std::isnan(value)) return "-";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

// fps of trackers that do almost nothing (the static one) is meaningless beyond this.
std::string fps_cell(double fps) { return fps > 10000.0 ? ">10000" : fixed(fps, 1); }

// Rows grouped by sequence (in order of first appearance), trackers in their given order.
std::vector<const SequenceScore*> by_sequence(std::vector<const SequenceScore*> rows) {
  std::map<std::string, size_t> first;
  for (const SequenceScore* s : rows) first.emplace(s->sequence, first.size());
  std::stable_sort(rows.begin(), rows.end(), [&](const SequenceScore* a, const SequenceScore* b) {
    return first[a->sequence] < first[b->sequence];
  });
  return rows;
}

void success_table(std::ostream& out, const std::vector<const SequenceScore*>& rows) {
  out << "| Sequence | Tracker | Frames | S@5 | S@10 | S@20 | Mean E_AL | Median E_AL | AUC | "
         "Failures |\n"
         "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  // The best AUC of each sequence is in bold.
  std::map<std::string, double> best;
  for (const SequenceScore* s : rows) {
    auto [it, inserted] = best.emplace(s->sequence, s->errors.auc);
    if (!inserted && s->errors.auc > it->second) it->second = s->errors.auc;
  }
  std::set<std::string> several;
  std::map<std::string, int> count;
  for (const SequenceScore* s : rows) {
    if (++count[s->sequence] > 1) several.insert(s->sequence);
  }
  for (const SequenceScore* s : rows) {
    const ErrorStats& e = s->errors;
    const bool bold = several.count(s->sequence) > 0 && e.auc == best[s->sequence];
    const std::string auc = fixed(e.auc, 3);
    out << "| " << s->sequence << " | " << s->tracker << " | " << e.frames << " | "
        << percent(e.success_5) << " | " << percent(e.success_10) << " | " << percent(e.success_20)
        << " | " << fixed(e.mean, 2) << " | " << fixed(e.median, 2) << " | "
        << (bold ? "**" + auc + "**" : auc) << " | " << e.failures << " |\n";
  }
}

}  // namespace

void write_summary_csv(std::ostream& out, const std::vector<SequenceScore>& scores) {
  bool first = true;
  for (const char* column : kSummaryColumns) {
    out << (first ? "" : ",") << column;
    first = false;
  }
  out << '\n';
  for (const SequenceScore& s : scores) {
    check_name(s.tracker);
    check_name(s.sequence);
    const ErrorStats& e = s.errors;
    out << s.tracker << ',' << s.sequence << ',' << e.frames << ',' << e.failures << ','
        << number(e.success_5) << ',' << number(e.success_10) << ',' << number(e.success_20) << ','
        << number(e.auc) << ',' << number(e.mean) << ',' << number(e.median);
    const TimingStats& t = s.timing;
    if (t.has_timing) {
      out << ',' << t.tracked << ',' << t.held << ',' << number(t.edges) << ',' << number(t.nodes)
          << ',' << number(t.line_ms) << ',' << number(t.grouping_ms) << ',' << number(t.track_ms)
          << ',' << number(t.fps);
    } else {
      out << ",,,,,,,,";
    }
    out << '\n';
  }
}

std::vector<SequenceScore> read_summary_csv(std::istream& in) {
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error("summary CSV: empty input");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::vector<std::string> header = split_commas(line);
  std::map<std::string, size_t> column;
  for (size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
  for (const char* name : kSummaryColumns) {
    if (column.count(name) == 0) {
      throw std::runtime_error(std::string("summary CSV: header lacks column '") + name + "'");
    }
  }
  std::vector<SequenceScore> scores;
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> fields = split_commas(line);
    auto bad = [&](const std::string& why) {
      return std::runtime_error("summary CSV line " + std::to_string(line_number) + ": " + why);
    };
    if (fields.size() != header.size()) {
      throw bad(std::to_string(fields.size()) + " fields, header has " +
                std::to_string(header.size()));
    }
    auto field = [&](const char* name) -> const std::string& { return fields[column[name]]; };
    auto real = [&](const char* name) {
      const std::string& text = field(name);
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size()) {
        throw bad(std::string(name) + " '" + text + "' is not a number");
      }
      return value;
    };
    auto integer = [&](const char* name) {
      const double value = real(name);
      if (value != std::floor(value) || std::fabs(value) > 2e9) {
        throw bad(std::string(name) + " '" + field(name) + "' is not an integer");
      }
      return static_cast<int>(value);
    };
    SequenceScore s;
    s.tracker = field("tracker");
    s.sequence = field("sequence");
    s.errors.frames = integer("frames");
    s.errors.failures = integer("failures");
    s.errors.success_5 = real("success_5");
    s.errors.success_10 = real("success_10");
    s.errors.success_20 = real("success_20");
    s.errors.auc = real("auc");
    s.errors.mean = real("mean_e_al");
    s.errors.median = real("median_e_al");
    s.timing.has_timing = !field("tracked").empty();
    if (s.timing.has_timing) {
      s.timing.tracked = integer("tracked");
      s.timing.held = integer("held");
      s.timing.edges = real("edges");
      s.timing.nodes = real("nodes");
      s.timing.line_ms = real("line_ms");
      s.timing.grouping_ms = real("grouping_ms");
      s.timing.track_ms = real("track_ms");
      s.timing.fps = real("fps");
    }
    scores.push_back(std::move(s));
  }
  return scores;
}

void write_frame_csv_header(std::ostream& out) {
  out << "tracker,sequence,frame,e_al,held,nodes,edges,line_ms,grouping_ms,track_ms,note\n";
}

void write_frame_csv_rows(std::ostream& out, const std::string& tracker,
                          const std::string& sequence, const std::vector<FrameRecord>& frames) {
  check_name(tracker);
  check_name(sequence);
  for (const FrameRecord& f : frames) {
    out << tracker << ',' << sequence << ',' << f.frame << ',' << number(f.e_al);
    if (f.has_timing) {
      out << ',' << (f.held ? 1 : 0) << ',' << f.nodes << ',' << f.edges << ',' << number(f.line_ms)
          << ',' << number(f.grouping_ms) << ',' << number(f.track_ms);
    } else {
      out << ",,,,,,";
    }
    // The note is free text: quoted, with quotes doubled.
    out << ',';
    if (!f.note.empty()) {
      out << '"';
      for (char c : f.note) {
        if (c == '"') out << '"';
        out << (c == '\n' || c == '\r' ? ' ' : c);
      }
      out << '"';
    }
    out << '\n';
  }
}

void write_curves_csv(std::ostream& out, const std::vector<NamedCurve>& curves) {
  out << "tracker,sequence,threshold,success_rate\n";
  for (const NamedCurve& c : curves) {
    check_name(c.tracker);
    check_name(c.sequence);
    for (size_t i = 0; i < c.curve.thresholds.size() && i < c.curve.rates.size(); ++i) {
      out << c.tracker << ',' << c.sequence << ',' << number(c.curve.thresholds[i]) << ','
          << number(c.curve.rates[i]) << '\n';
    }
  }
}

void write_markdown_report(std::ostream& out, const std::vector<SequenceScore>& scores,
                           const ReportInfo& info) {
  out << "# " << info.title << "\n\n";
  if (!info.dataset.empty()) out << "Dataset: `" << info.dataset << "`\n\n";
  for (const std::string& note : info.notes) out << "- " << note << '\n';
  if (!info.notes.empty()) out << '\n';

  std::vector<const SequenceScore*> per_sequence, pooled, timed;
  for (const SequenceScore& s : scores) {
    (s.sequence == kAllSequences ? pooled : per_sequence).push_back(&s);
    if (s.timing.has_timing && s.sequence != kAllSequences) timed.push_back(&s);
  }
  out << "## Success rate per sequence\n\n"
         "S@e = share of frames with E_AL < e px. Mean E_AL is over the scored frames; failed "
         "frames (missing or degenerate boundary) count as infinite error in S@e, the median and "
         "the AUC (area under the success curve over e = 0..50 px, normalised to 0..1; the "
         "best per sequence in bold).\n\n";
  success_table(out, by_sequence(per_sequence));
  if (!pooled.empty()) {
    out << "\n## All sequences pooled\n\nEvery frame of every sequence counted once.\n\n";
    success_table(out, pooled);
  }
  if (!timed.empty()) {
    out << "\n## Graph scale and time efficiency (the paper's Table I)\n\n"
           "Means over the tracked frames (the initial frame excluded): graph edges and nodes, "
           "line detection time lt, grouping time gt, and fps = the mean over frames of the "
           "instantaneous 1000 / (wall time of one track() call in ms). Held = frames where the "
           "tracker kept its previous boundary.\n\n"
           "| Sequence | Tracker | Edges | Nodes | lt (ms) | gt (ms) | Track (ms) | fps | Held |\n"
           "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const SequenceScore* s : by_sequence(timed)) {
      const TimingStats& t = s->timing;
      out << "| " << s->sequence << " | " << s->tracker << " | " << fixed(t.edges, 0) << " | "
          << fixed(t.nodes, 0) << " | " << fixed(t.line_ms, 2) << " | " << fixed(t.grouping_ms, 2)
          << " | " << fixed(t.track_ms, 2) << " | " << fps_cell(t.fps) << " | " << t.held << "/"
          << t.tracked << " |\n";
    }
  }
  if (!info.plot_file.empty()) {
    out << "\n## Success curves\n\n![Success rate against the E_AL threshold](" << info.plot_file
        << ")\n";
  }
}

}  // namespace scbt
