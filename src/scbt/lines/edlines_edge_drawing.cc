#include <algorithm>

#include "scbt/lines/edlines.h"
#include "scbt/lines/edlines_maps.h"

namespace scbt {

using namespace edlines_maps;  // NOLINT(build/namespaces): the map codes the stages share

void EdLines::draw_edges() {
  for (int anchor : sorted_anchors_) {
    if (edge_[anchor] != kAnchor) continue;  // already on an edge, or cleared
    walk_from_anchor(anchor);
  }
}

void EdLines::walk_from_anchor(int anchor) {
  const int w = width_;
  chains_.clear();
  stack_.clear();
  chain_pixels_.clear();
  chains_.push_back({-1, 0, 0, {-1, -1}});
  if (dir_[anchor] == kVertical) {
    stack_.push_back({anchor, kDown, 0});
    stack_.push_back({anchor, kUp, 0});
  } else {
    stack_.push_back({anchor, kRight, 0});
    stack_.push_back({anchor, kLeft, 0});
  }
  int shared_starts = 0;  // start pixels counted twice
  while (!stack_.empty()) {
    const StackNode node = stack_.back();
    stack_.pop_back();
    if (edge_[node.pixel] != kEdge) ++shared_starts;
    const bool horizontal = node.dir == kLeft || node.dir == kRight;
    const std::uint8_t want = horizontal ? kHorizontal : kVertical;
    // Ahead, and the two diagonal pixels ahead ("a" before "c" when tied edges exist).
    int ahead, side_a, side_c;
    switch (node.dir) {
      case kLeft:
        ahead = -1, side_a = -w, side_c = w;
        break;
      case kRight:
        ahead = 1, side_a = w, side_c = -w;
        break;
      case kUp:
        ahead = -w, side_a = -1, side_c = 1;
        break;
      default:
        ahead = w, side_a = 1, side_c = -1;
        break;
    }
    const int side = horizontal ? w : 1;  // across the edge
    Chain chain{node.dir, 1, static_cast<int>(chain_pixels_.size()), {-1, -1}};
    int p = node.pixel;
    chain_pixels_.push_back(p);
    bool turned = false;
    while (true) {
      if (dir_[p] != want) {
        turned = true;
        break;
      }
      edge_[p] = kEdge;
      if (edge_[p - side] == kAnchor) edge_[p - side] = 0;  // anchors beside the edge
      if (edge_[p + side] == kAnchor) edge_[p + side] = 0;
      const int straight = p + ahead, first = straight + side_a, second = straight + side_c;
      if (edge_[straight] != 0) {
        p = straight;
      } else if (edge_[first] != 0) {
        p = first;
      } else if (edge_[second] != 0) {
        p = second;
      } else {
        // Follow the ridge: the largest gradient of the three ahead; on ties the straight one,
        // then the one on the plus side (row below, or column to the right).
        const int minus = straight - side, plus = straight + side;
        const int gs = grad_[straight], gm = grad_[minus], gp = grad_[plus];
        if (gm > gs) {
          p = gm > gp ? minus : plus;
        } else {
          p = gp > gs ? plus : straight;
        }
      }
      if (edge_[p] == kEdge || dir_[p] == 0) break;
      chain_pixels_.push_back(p);
      ++chain.len;
    }
    const int index = static_cast<int>(chains_.size());
    if (turned) {
      // p turns the edge: two chains go on from it across this one; p is their first pixel.
      if (horizontal) {
        stack_.push_back({p, kDown, index});
        stack_.push_back({p, kUp, index});
      } else {
        stack_.push_back({p, kRight, index});
        stack_.push_back({p, kLeft, index});
      }
      chain_pixels_.pop_back();
      --chain.len;
    }
    chains_.push_back(chain);
    chains_[node.parent].children[node.dir <= kUp ? 0 : 1] = index;
  }

  const int walked = static_cast<int>(chain_pixels_.size());
  if (walked - shared_starts < params_.min_path_length) {
    for (int q : chain_pixels_) edge_[q] = 0;
    return;
  }

  // One segment: the longest path on the second side reversed, then the first side's.
  if (longest_chain(chains_[0].children[1]) > 0) {
    path_.clear();
    for (int k = chains_[0].children[1]; k >= 0;) {
      path_.push_back(k);
      k = chains_[k].children[0] >= 0 ? chains_[k].children[0] : chains_[k].children[1];
    }
    for (int i = static_cast<int>(path_.size()) - 1; i >= 0; --i) append_chain(path_[i], true, 0);
  }
  if (longest_chain(chains_[0].children[0]) > 1) {
    path_.clear();
    for (int k = chains_[0].children[0]; k >= 0;) {
      path_.push_back(k);
      k = chains_[k].children[0] >= 0 ? chains_[k].children[0] : chains_[k].children[1];
    }
    for (size_t i = 0; i < path_.size(); ++i) append_chain(path_[i], false, i == 0 ? 1 : 0);
  }
  close_segment(true);

  // Other long branches become segments of their own.
  const int count = static_cast<int>(chains_.size());
  for (int k = 2; k < count; ++k) {
    if (chains_[k].len < 2) continue;
    if (longest_chain(k) < params_.min_path_length) continue;
    path_.clear();
    for (int j = k; j >= 0;) {
      path_.push_back(j);
      j = chains_[j].children[0] >= 0 ? chains_[j].children[0] : chains_[j].children[1];
    }
    for (int j : path_) append_chain(j, false, 0);
    close_segment(false);
  }
}

// Length of the longest root-to-leaf path under `root` (0 for none); prunes every node to its
// longer child so that following children walks that path.
int EdLines::longest_chain(int root) {
  if (root < 0 || chains_[root].len == 0) return 0;
  best_.resize(chains_.size());
  order_.clear();
  dfs_.clear();
  dfs_.push_back(root);
  while (!dfs_.empty()) {
    const int k = dfs_.back();
    dfs_.pop_back();
    order_.push_back(k);
    for (int c : chains_[k].children) {
      if (c >= 0 && chains_[c].len > 0) dfs_.push_back(c);
    }
  }
  for (auto it = order_.rbegin(); it != order_.rend(); ++it) {
    Chain& chain = chains_[*it];
    int lengths[2] = {0, 0};
    for (int s = 0; s < 2; ++s) {
      const int c = chain.children[s];
      if (c >= 0 && chains_[c].len > 0) lengths[s] = best_[c];
    }
    if (lengths[0] >= lengths[1]) {
      chain.children[1] = -1;
      if (lengths[0] == 0) chain.children[0] = -1;
    } else {
      chain.children[0] = -1;
    }
    best_[*it] = chain.len + std::max(lengths[0], lengths[1]);
  }
  return best_[root];
}

// Appends a chain's pixels (reversed or not, skipping `skip_first` of them) to the open segment,
// dropping pixels that would make a corner with it, and marks the chain copied.
void EdLines::append_chain(int chain_index, bool reversed, int skip_first) {
  Chain& chain = chains_[chain_index];
  const int n = chain.len - skip_first;
  if (n <= 0) {
    chain.len = 0;
    return;
  }
  const int* pixels = chain_pixels_.data() + chain.first;
  auto at = [&](int i) { return reversed ? pixels[chain.len - 1 - i] : pixels[skip_first + i]; };
  const size_t begin = static_cast<size_t>(open_begin_);
  // Pixels of the open segment before its last one that touch the new first pixel make the last
  // one a detour: drop it.
  const int head = at(0);
  while (seg_pixels_.size() >= begin + 2 &&
         adjacent(head, seg_pixels_[seg_pixels_.size() - 2], width_)) {
    seg_pixels_.pop_back();
  }
  int start = 0;
  if (n > 1 && seg_pixels_.size() > begin && adjacent(at(1), seg_pixels_.back(), width_)) start = 1;
  for (int i = start; i < n; ++i) seg_pixels_.push_back(at(i));
  chain.len = 0;
}

// Ends the open segment; an anchor's main segment drops its first pixel when its second one
// touches the last (a closed edge).
void EdLines::close_segment(bool main) {
  const int end = static_cast<int>(seg_pixels_.size());
  int begin = open_begin_;
  if (main && end - begin >= 2 && adjacent(seg_pixels_[begin + 1], seg_pixels_[end - 1], width_)) {
    ++begin;
  }
  if (end > begin) {
    seg_start_.push_back(begin);
    seg_end_.push_back(end);
  }
  open_begin_ = end;
}

}  // namespace scbt
