#include "viewer_page.h"

#include <algorithm>
#include <bit>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string_view>

#include <dlfl/errors.h>
#include <dlfl/navigation.h>
#include <dlfl/render/colors.h>
#include <dlfl/statistics.h>
#include "viewer_template.h"  // generated from tools/viewer/ (viewer_template.cmake)

namespace dlfl::tool {

namespace {

// Base64 of little-endian bytes, written as they come: the typed arrays the page decodes. Its alphabet needs
// no escaping in JSON or HTML, so the arrays go to the page without a copy.
class Base64Writer {
 public:
  explicit Base64Writer(std::ostream& out) : out_(out) {}
  template <class T>
  void values(const std::vector<T>& values) {
    for (const T value : values) {
      if constexpr (sizeof(T) == 1) {
        byte(value);
      } else {
        const auto bits = std::bit_cast<std::uint32_t>(value);
        for (int shift = 0; shift < 32; shift += 8) byte(static_cast<std::uint8_t>(bits >> shift));
      }
    }
  }
  // Pads the last group and writes what is held.
  void finish() {
    if (held_ > 0) {
      for (int k = held_; k < 3; ++k) group_[k] = 0;
      emit(held_ + 1);
    }
    out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
    text_.clear();
  }

 private:
  void byte(std::uint8_t b) {
    group_[held_++] = b;
    if (held_ == 3) emit(4);
  }
  void emit(int digits) {
    static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const std::uint32_t bits = std::uint32_t{group_[0]} << 16 | std::uint32_t{group_[1]} << 8 | group_[2];
    for (int k = 0; k < 4; ++k) text_.push_back(k < digits ? alphabet[(bits >> (18 - 6 * k)) & 63] : '=');
    held_ = 0;
    if (text_.size() >= (1u << 16)) finish();
  }
  std::ostream& out_;
  std::uint8_t group_[3] = {0, 0, 0};
  int held_ = 0;
  std::string text_;
};

template <class T>
void write_array(std::ostream& out, const char* name, const std::vector<T>& values) {
  out << ",\"" << name << "\":\"";
  Base64Writer base64(out);
  base64.values(values);
  base64.finish();
  out << '"';
}

std::string hex_color(Rgba c) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string text = "#";
  for (const std::uint8_t channel : {c.r, c.g, c.b}) {
    text.push_back(hex[channel >> 4]);
    text.push_back(hex[channel & 15]);
  }
  return text;
}

// JSON inside <script> must not close the element: '<' only occurs in strings, where \u003c means the same.
void write_script_safe(std::ostream& out, std::string_view json_text) {
  for (std::size_t at = 0; at < json_text.size();) {
    const std::size_t lt = std::min(json_text.find('<', at), json_text.size());
    out.write(json_text.data() + at, static_cast<std::streamsize>(lt - at));
    if (lt < json_text.size()) out << "\\u003c";
    at = lt + 1;
  }
}

std::string html_escaped(std::string_view raw) {
  std::string text;
  for (const char c : raw) {
    switch (c) {
      case '<':
        text += "&lt;";
        break;
      case '>':
        text += "&gt;";
        break;
      case '&':
        text += "&amp;";
        break;
      case '"':
        text += "&quot;";
        break;
      default:
        text.push_back(c);
    }
  }
  return text;
}

std::string step_counts(const MeshStatistics& stats) {
  std::string text = "V " + std::to_string(stats.vertices) + ", E " + std::to_string(stats.edges) + ", F " +
                     std::to_string(stats.faces);
  if (stats.holes > 0) text += ", " + std::to_string(stats.holes) + (stats.holes == 1 ? " hole" : " holes");
  return text;
}

}  // namespace

void ViewerPage::check_room(std::size_t faces_to_come) const {
  if (faces_ + faces_to_come <= max_faces_) return;
  throw Error("the page would hold " + std::to_string(faces_ + faces_to_come) +
              " faces, more than a browser draws comfortably (--max-faces " + std::to_string(max_faces_) +
              "); view fewer steps or a smaller mesh");
}

void ViewerPage::add(const Mesh& mesh, std::string label) {
  const MeshStatistics stats = statistics(mesh);
  check_room(stats.faces);
  if (!centre_) centre_ = (stats.bbox_min + stats.bbox_max) * 0.5;
  ViewerStep step;
  step.label = std::move(label);
  step.counts = step_counts(stats);
  step.faces = stats.faces;
  step.bbox_min = stats.bbox_min - *centre_;
  step.bbox_max = stats.bbox_max - *centre_;
  for (const auto& [sides, count] : stats.face_sizes) step.face_sizes.emplace_back(sides, count);

  std::vector<std::uint32_t> index(mesh.vertex_capacity());
  step.positions.reserve(3 * mesh.num_vertices());
  for (const VertexId v : mesh.vertices()) {
    index[v.index()] = static_cast<std::uint32_t>(step.positions.size() / 3);
    const glm::dvec3 p = mesh.position(v) - *centre_;
    step.positions.insert(step.positions.end(),
                          {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
  }
  for (const FaceId f : surface_faces(mesh)) {
    if (mesh.size(f) < 3) continue;  // point spheres and 2-gons cover no area
    const Rgba color = face_size_color(mesh.size(f));
    const std::uint32_t apex = index[mesh.vertex(mesh.first_corner(f)).index()];
    CornerId c = mesh.next(mesh.first_corner(f));
    for (std::uint32_t k = 2; k < mesh.size(f); ++k, c = mesh.next(c)) {
      step.triangles.insert(step.triangles.end(),
                            {apex, index[mesh.vertex(c).index()], index[mesh.vertex(mesh.next(c)).index()]});
      step.triangle_colors.insert(step.triangle_colors.end(), {color.r, color.g, color.b});
    }
  }
  for (const EdgeId e : mesh.edges()) {
    if (mesh.is_hole(mesh.face(e, 0)) && mesh.is_hole(mesh.face(e, 1))) continue;  // inside a covered hole
    step.edges.insert(step.edges.end(), {index[mesh.from(e).index()], index[mesh.to(e).index()]});
  }
  faces_ += step.faces;
  steps_.push_back(std::move(step));
}

void ViewerPage::write(std::ostream& out, const std::string& title) const {
  // The template holds the title's marker, then the data's.
  const std::string_view page = viewer_template;
  const std::string_view title_marker = "@DLFL_TITLE@", data_marker = "@DLFL_DATA@";
  const std::size_t title_at = page.find(title_marker), data_at = page.find(data_marker);
  if (title_at == page.npos || data_at == page.npos || data_at < title_at)
    throw Error("the viewer template lacks its markers");  // a build fault: viewer.html was edited wrongly
  const std::size_t after_title = title_at + title_marker.size();
  out << page.substr(0, title_at) << html_escaped(title) << page.substr(after_title, data_at - after_title);
  // The data: the small fields through nlohmann-json, the arrays written straight after them.
  write_script_safe(out, "{\"title\":" + nlohmann::json(title).dump() + ",\"steps\":[");
  for (std::size_t k = 0; k < steps_.size(); ++k) {
    const ViewerStep& step = steps_[k];
    nlohmann::json legend = nlohmann::json::array();
    for (const auto& [sides, count] : step.face_sizes)
      legend.push_back({sides, count, hex_color(face_size_color(sides))});
    const nlohmann::json fields = {{"label", step.label},
                                   {"counts", step.counts},
                                   {"faces", step.faces},
                                   {"bbox",
                                    {{step.bbox_min.x, step.bbox_min.y, step.bbox_min.z},
                                     {step.bbox_max.x, step.bbox_max.y, step.bbox_max.z}}},
                                   {"face_sizes", legend}};
    const std::string text = fields.dump();
    write_script_safe(out, std::string(k > 0 ? "," : "") + text.substr(0, text.size() - 1));  // without its }
    write_array(out, "positions", step.positions);
    write_array(out, "triangles", step.triangles);
    write_array(out, "triangle_colors", step.triangle_colors);
    write_array(out, "edges", step.edges);
    out << '}';
  }
  out << "]}" << page.substr(data_at + data_marker.size());
}

}  // namespace dlfl::tool
