#include "scbt/cycles/segment_units.h"

#include <algorithm>

namespace scbt {

namespace {

// Both ends keep an arc for every pair of units they share, so each arc has its reverse: found
// from the lower unit's side, set both ways.
void find_reverse_arcs(SegmentUnits* units) {
  const std::vector<int>& begin = units->arc_begin;
  const std::vector<SegmentUnits::Arc>& arcs = units->arcs;
  units->reverse.resize(arcs.size());
  for (int x = 0; x < units->num_units; ++x) {
    for (int k = begin[x]; k < begin[x + 1]; ++k) {
      const int y = arcs[k].unit;
      if (y < x) continue;
      int j = begin[y];
      while (arcs[j].unit != x) ++j;
      units->reverse[k] = j;
      units->reverse[j] = k;
    }
  }
}

}  // namespace

void build_segment_units(const SegmentGraph& graph, SegmentUnits* units) {
  const int n = graph.num_vertices();
  // Detected edges per vertex; a segment whose two ends have no other one becomes a unit.
  std::vector<int>& partner = units->partner;
  partner.assign(n, -1);
  std::vector<int>& detected_degree = units->scratch_count;
  detected_degree.assign(n, 0);
  for (int e : graph.detected_edges) {
    ++detected_degree[graph.edges[e].u];
    ++detected_degree[graph.edges[e].v];
  }
  for (int e : graph.detected_edges) {
    const int a = graph.edges[e].u, b = graph.edges[e].v;
    if (a != b && detected_degree[a] == 1 && detected_degree[b] == 1) {
      partner[a] = b;
      partner[b] = a;
    }
  }
  std::vector<int>& unit_of = units->unit_of;
  unit_of.assign(n, -1);
  int num_units = 0;
  for (int v = 0; v < n; ++v) {
    if (unit_of[v] >= 0) continue;
    unit_of[v] = num_units;
    if (partner[v] >= 0) unit_of[partner[v]] = num_units;
    ++num_units;
  }
  units->num_units = num_units;

  // Arcs: per unit, the lightest edge to each other unit (`slot` finds a neighbour's arc).
  std::vector<int>& begin = units->arc_begin;
  std::vector<SegmentUnits::Arc>& arcs = units->arcs;
  begin.assign(num_units + 1, 0);
  arcs.clear();
  std::vector<int>& slot_stamp = units->scratch_stamp;
  std::vector<int>& slot = units->scratch_slot;
  slot_stamp.assign(num_units, -1);
  slot.resize(num_units);
  int u = 0;
  for (int v = 0; v < n; ++v) {
    if (unit_of[v] != u) continue;  // each unit once, from its first vertex
    for (const int member : {v, partner[v]}) {
      if (member < 0) continue;
      for (int k = graph.adjacency_begin[member]; k < graph.adjacency_begin[member + 1]; ++k) {
        const SegmentGraph::Incidence& in = graph.adjacency[k];
        const int target = unit_of[in.vertex];
        if (target == u) continue;
        const double weight = graph.edges[in.edge].weight;
        if (slot_stamp[target] != u) {
          slot_stamp[target] = u;
          slot[target] = static_cast<int>(arcs.size());
          arcs.push_back({target, member, in.vertex, weight});
        } else if (weight < arcs[slot[target]].weight) {
          arcs[slot[target]] = {target, member, in.vertex, weight};
        }
      }
    }
    // By weight, so that a bounded search stops relaxing at the first arc past its bound.
    std::sort(
        arcs.begin() + begin[u], arcs.end(),
        [](const SegmentUnits::Arc& l, const SegmentUnits::Arc& r) { return l.weight < r.weight; });
    begin[++u] = static_cast<int>(arcs.size());
  }

  find_reverse_arcs(units);
}

void drop_dominated_arcs(const std::vector<int>& opened_by, double margin, SegmentUnits* units) {
  const int num_units = units->num_units;
  std::vector<int>& begin = units->arc_begin;
  std::vector<SegmentUnits::Arc>& arcs = units->arcs;
  // Per neighbour z of the current unit x: the weight of x - z and the vertex of z it reaches,
  // by stamp.
  std::vector<int>& stamp = units->scratch_stamp;
  std::vector<int>& dropped = units->scratch_count;
  stamp.assign(num_units, -1);
  dropped.assign(arcs.size(), 0);
  std::vector<double>& weight_to = units->scratch_weight;
  weight_to.resize(num_units);
  std::vector<int>& reaches = units->scratch_slot;
  reaches.resize(num_units);
  for (int x = 0; x < num_units; ++x) {
    for (int k = begin[x]; k < begin[x + 1]; ++k) {
      stamp[arcs[k].unit] = x;
      weight_to[arcs[k].unit] = arcs[k].weight;
      reaches[arcs[k].unit] = arcs[k].to;
    }
    for (int k = begin[x]; k < begin[x + 1]; ++k) {
      const int y = arcs[k].unit;
      const double c = arcs[k].weight;
      // Each pair once; a detour weighs at least the lightest arcs of x and y (first in their
      // sorted lists) together.
      if (y < x || !(arcs[begin[x]].weight + arcs[begin[y]].weight < c - margin)) continue;
      int first = -3;  // the opener of the first detour found (-3: none yet)
      bool dominated = false;
      for (int j = begin[y]; j < begin[y + 1] && !dominated; ++j) {
        const int z = arcs[j].unit;
        if (z == x || stamp[z] != x || !(weight_to[z] + arcs[j].weight < c - margin)) continue;
        const int opener = reaches[z] == arcs[j].to ? -1 : opened_by[z];
        if (opener == -1) {
          dominated = true;
        } else if (opener >= 0) {
          if (first == -3) first = opener;
          dominated = opener != first;
        }
      }
      if (dominated) dropped[k] = dropped[units->reverse[k]] = 1;
    }
  }
  // Compact every unit's arcs in place (their order by weight kept); `dropped` becomes each
  // kept arc's new index, by which the reverse indices follow.
  std::vector<int>& reverse = units->reverse;
  int kept = 0;
  for (int x = 0; x < num_units; ++x) {
    const int end = begin[x + 1];
    int k = begin[x];
    begin[x] = kept;
    for (; k < end; ++k) {
      if (dropped[k]) continue;
      dropped[k] = kept;
      arcs[kept] = arcs[k];
      reverse[kept++] = reverse[k];
    }
  }
  begin[num_units] = kept;
  arcs.resize(kept);
  reverse.resize(kept);
  for (int& r : reverse) r = dropped[r];
}

}  // namespace scbt
