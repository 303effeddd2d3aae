// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/contour_fill.h"

#include <cstdint>
#include <deque>
#include <vector>

namespace isovdb::morph {

namespace {

/// Component labels of `mask == value` on a grid padded by one background pixel
/// (so all outside background is one component, label 0 when value is background).
struct Labels {
  int width = 0, height = 0;
  std::vector<int> label;  ///< -1: other class
  int count = 0;
};

Labels labelComponents(const std::vector<std::uint8_t>& padded, int w, int h, std::uint8_t value, bool eight) {
  Labels out{w, h, std::vector<int>(padded.size(), -1), 0};
  std::vector<int> stack;
  for (int start = 0; start < w * h; ++start) {
    if (padded[start] != value || out.label[start] >= 0) continue;
    const int id = out.count++;
    out.label[start] = id;
    stack.push_back(start);
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      const int x = p % w, y = p / w;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx == 0 && dy == 0) || (!eight && dx != 0 && dy != 0)) continue;
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          const int q = ny * w + nx;
          if (padded[q] == value && out.label[q] < 0) {
            out.label[q] = id;
            stack.push_back(q);
          }
        }
    }
  }
  return out;
}

}  // namespace

Mask2 fillContours(const Mask2& foreground) {
  const int w = foreground.width + 2, h = foreground.height + 2;
  std::vector<std::uint8_t> padded(static_cast<std::size_t>(w) * h, 0);
  for (int y = 0; y < foreground.height; ++y)
    for (int x = 0; x < foreground.width; ++x) padded[(y + 1) * w + x + 1] = foreground.at(x, y) ? 1 : 0;
  const Labels fg = labelComponents(padded, w, h, 1, /*eight=*/true);
  const Labels bg = labelComponents(padded, w, h, 0, /*eight=*/false);

  // Thin components: no pixel with its four neighbours in the foreground.
  std::vector<std::uint8_t> thin(fg.count, 1);
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      const int p = y * w + x;
      if (fg.label[p] < 0) continue;
      if (padded[p - 1] && padded[p + 1] && padded[p - w] && padded[p + w]) thin[fg.label[p]] = 0;
    }

  // Adjacency (4-neighbourhood) between background and foreground components.
  std::vector<std::vector<int>> bgToFg(bg.count), fgToBg(fg.count);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int p = y * w + x;
      if (bg.label[p] < 0) continue;
      const int nbs[4] = {x > 0 ? p - 1 : -1, x < w - 1 ? p + 1 : -1, y > 0 ? p - w : -1, y < h - 1 ? p + w : -1};
      for (int q : nbs) {
        if (q < 0 || fg.label[q] < 0) continue;
        const int a = bg.label[p], b = fg.label[q];
        if (bgToFg[a].empty() || bgToFg[a].back() != b) bgToFg[a].push_back(b);
        if (fgToBg[b].empty() || fgToBg[b].back() != a) fgToBg[b].push_back(a);
      }
    }

  // Breadth-first from the outside: each component is reached from the side that
  // encloses it; thin contours toggle inside/outside, filled regions do not.
  std::vector<int> bgInside(bg.count, -1);
  std::vector<std::uint8_t> fgSeen(fg.count, 0);
  std::deque<int> queue;
  const int outside = bg.label[0];
  bgInside[outside] = 0;
  queue.push_back(outside);
  while (!queue.empty()) {
    const int a = queue.front();
    queue.pop_front();
    for (int b : bgToFg[a]) {
      if (fgSeen[b]) continue;
      fgSeen[b] = 1;
      const int beyond = thin[b] ? 1 - bgInside[a] : bgInside[a];
      for (int c : fgToBg[b])
        if (bgInside[c] < 0) {
          bgInside[c] = beyond;
          queue.push_back(c);
        }
    }
  }

  Mask2 out = Mask2::empty(foreground.width, foreground.height);
  for (int y = 0; y < foreground.height; ++y)
    for (int x = 0; x < foreground.width; ++x) {
      const int p = (y + 1) * w + x + 1;
      out.set(x, y, fg.label[p] >= 0 || bgInside[bg.label[p]] == 1);
    }
  return out;
}

}  // namespace isovdb::morph
