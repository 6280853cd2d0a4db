#pragma once
// The tables of dlfl_bench_peers: one row per cold measurement as it arrives, then per scheme and size the
// libraries side by side, and the scaling from the smallest to the largest size.

#include <cstddef>
#include <optional>
#include <vector>

#include "cold_runs.h"

namespace dlfl::bench {

/// Every library's measurement of one scheme at one size.
struct PeerRow {
  Scheme scheme = Scheme::catmull_clark;
  std::size_t n = 0;               ///< grid side of the input
  std::size_t expected_faces = 0;  ///< output faces in closed form
  std::optional<ColdResult> dlfl, dlfl_one_thread, cgal, openmesh;
};

void print_detail_header();
/// One measurement: step wall, user and system time, system share, page faults, peak RSS, output faces.
void print_detail(const PeerRow& row, const char* label, const std::optional<ColdResult>& r);

/// Whether every library that ran produced the closed-form number of faces.
bool faces_agree(const PeerRow& row);

/// Per scheme and size: dlfl (default threads and one), CGAL, OpenMesh, the ratios to dlfl, and each
/// library's system share of the step's CPU time.
void print_summary(const std::vector<PeerRow>& rows);

/// Per scheme and library: nanoseconds per output face at each size, and the ratio largest / smallest.
void print_scaling(const std::vector<PeerRow>& rows);

}  // namespace dlfl::bench
