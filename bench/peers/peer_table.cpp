// Printing dlfl_bench_peers' tables (peer_table.h).

#include "peer_table.h"

#include <cstdio>
#include <string>

namespace dlfl::bench {

namespace {

double step_seconds(const std::optional<ColdResult>& r) { return r ? r->step.cost.wall : 0; }

// "  1.234" or "     -" where the library has no such scheme.
std::string seconds_cell(const std::optional<ColdResult>& r) {
  char cell[32];
  if (r) {
    std::snprintf(cell, sizeof cell, "%9.3f", r->step.cost.wall);
  } else {
    std::snprintf(cell, sizeof cell, "%9s", "-");
  }
  return cell;
}

std::string ratio_cell(const std::optional<ColdResult>& a, const std::optional<ColdResult>& b) {
  char cell[32];
  if (a && b && b->step.cost.wall > 0) {
    std::snprintf(cell, sizeof cell, "%8.2fx", a->step.cost.wall / b->step.cost.wall);
  } else {
    std::snprintf(cell, sizeof cell, "%9s", "-");
  }
  return cell;
}

// The system share of a step's CPU time in percent, "  -" where the library has no such scheme.
std::string share_cell(const std::optional<ColdResult>& r) {
  char cell[16];
  const double cpu = r ? r->step.cost.user + r->step.cost.system : 0;
  if (cpu > 0) {
    std::snprintf(cell, sizeof cell, "%3.0f", 100 * r->step.cost.system / cpu);
  } else {
    std::snprintf(cell, sizeof cell, "%3s", "-");
  }
  return cell;
}

}  // namespace

void print_detail_header() {
  std::printf("%-14s %9s %-11s %9s %9s %9s %6s %10s %8s %10s %10s\n", "scheme", "n", "library", "step s",
              "user s", "sys s", "sys %", "min flt", "maj flt", "peak MiB", "out faces");
}

void print_detail(const PeerRow& row, const char* label, const std::optional<ColdResult>& r) {
  if (!r) return;
  const StepCost& c = r->step.cost;
  const double cpu = c.user + c.system;
  std::printf("%-14s %9zu %-11s %9.3f %9.3f %9.3f %5.1f%% %10ld %8ld %10.1f %10zu%s\n",
              scheme_name(row.scheme), row.n, label, c.wall, c.user, c.system,
              cpu > 0 ? 100 * c.system / cpu : 0.0, c.minor_faults, c.major_faults, r->peak_rss_mib,
              r->step.output_faces,
              r->step.output_faces == row.expected_faces ? "" : "  FACE COUNT MISMATCH");
  std::fflush(stdout);
}

bool faces_agree(const PeerRow& row) {
  for (const auto* r : {&row.dlfl, &row.dlfl_one_thread, &row.cgal, &row.openmesh}) {
    if (*r && (*r)->step.output_faces != row.expected_faces) return false;
  }
  return true;
}

void print_summary(const std::vector<PeerRow>& rows) {
  std::printf("\nstep wall seconds (median of cold runs); ratios > 1: dlfl is faster\n");
  std::printf("%-14s %10s %9s %9s %9s %9s %9s %9s %9s  %s\n", "scheme", "out faces", "dlfl", "dlfl 1T",
              "2T vs 1T", "CGAL", "OpenMesh", "CGAL/dlfl", "OM/dlfl", "sys %: dlfl/CGAL/OM");
  for (const PeerRow& row : rows) {
    std::printf("%-14s %10zu %s %s %s %s %s %s %s  %s/%s/%s%s\n", scheme_name(row.scheme), row.expected_faces,
                seconds_cell(row.dlfl).c_str(), seconds_cell(row.dlfl_one_thread).c_str(),
                ratio_cell(row.dlfl_one_thread, row.dlfl).c_str(), seconds_cell(row.cgal).c_str(),
                seconds_cell(row.openmesh).c_str(), ratio_cell(row.cgal, row.dlfl).c_str(),
                ratio_cell(row.openmesh, row.dlfl).c_str(), share_cell(row.dlfl).c_str(),
                share_cell(row.cgal).c_str(), share_cell(row.openmesh).c_str(),
                faces_agree(row) ? "" : "  FACE COUNT MISMATCH");
  }
}

void print_scaling(const std::vector<PeerRow>& rows) {
  std::printf("\nnanoseconds per output face; last column: largest size / smallest (1 = linear)\n");
  std::printf("%-14s %-9s", "scheme", "library");
  std::size_t sizes = 0;
  for (const PeerRow& row : rows) {
    if (row.scheme != rows.front().scheme) break;
    std::printf(" %10zu", row.expected_faces);
    ++sizes;
  }
  std::printf(" %9s\n", "scaling");
  struct Column {
    const char* label;
    std::optional<ColdResult> PeerRow::*member;
  };
  const Column columns[] = {
      {"dlfl", &PeerRow::dlfl}, {"CGAL", &PeerRow::cgal}, {"OpenMesh", &PeerRow::openmesh}};
  for (std::size_t first = 0; first + sizes <= rows.size() && sizes > 0; first += sizes) {
    for (const Column& column : columns) {
      if (!(rows[first].*column.member)) continue;
      std::printf("%-14s %-9s", scheme_name(rows[first].scheme), column.label);
      double smallest = 0, largest = 0;
      for (std::size_t i = first; i < first + sizes; ++i) {
        const double ns = 1e9 * step_seconds(rows[i].*column.member) / double(rows[i].expected_faces);
        std::printf(" %10.1f", ns);
        if (i == first) smallest = ns;
        largest = ns;
      }
      if (sizes > 1 && smallest > 0) {
        std::printf(" %8.2fx\n", largest / smallest);
      } else {
        std::printf(" %9s\n", "-");
      }
    }
  }
}

}  // namespace dlfl::bench
