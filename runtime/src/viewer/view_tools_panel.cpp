// The panel's camera part (param_panel.hpp, draw_view_tools): the view the
// window shows, the bookmarks and the hi-res render.
#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>

#include "viewer/param_panel.hpp"

namespace sdfc::viewer {

bool draw_view_tools(ViewTools& tools) {
  bool moved = false;
  const ir::Camera c = tools.rig().camera();
  ImGui::TextDisabled("view: position [%.3g, %.3g, %.3g]  fov %.3g", c.position[0], c.position[1], c.position[2],
                      c.fov_degrees);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("C prints it as a camera line; Shift+1...9 keeps it, 1...9 goes back");
  ImGui::PopStyleColor();
  if (!tools.bookmarks().list().empty()) {
    ImGui::Text("bookmarks:");
    for (const auto& b : tools.bookmarks().list()) {
      ImGui::SameLine();
      if (ImGui::SmallButton(fmt::format("{}##bookmark", b.key).c_str()) && tools.recall(b.key)) moved = true;
    }
  }
  ImGui::PushItemWidth(70);
  ImGui::InputInt("##hires-w", &tools.hires_width, 0);
  ImGui::SameLine();
  ImGui::TextUnformatted("x");
  ImGui::SameLine();
  ImGui::InputInt("##hires-h", &tools.hires_height, 0);
  ImGui::SameLine();
  ImGui::InputInt("samples", &tools.hires_samples, 0);
  ImGui::PopItemWidth();
  tools.hires_width = std::clamp(tools.hires_width, 16, 16384);
  tools.hires_height = std::clamp(tools.hires_height, 16, 16384);
  tools.hires_samples = std::clamp(tools.hires_samples, 1, 1024);
  HiresRender& h = tools.hires();
  if (h.running()) {
    if (ImGui::Button("Cancel")) h.cancel();
    ImGui::SameLine();
    ImGui::ProgressBar(float(h.progress()), ImVec2(-1, 0));
  } else if (ImGui::Button("Render this view (H)")) {
    tools.start_hires();
  }
  const std::string status = h.status();
  if (!status.empty()) ImGui::TextWrapped("%s", status.c_str());
  if (!tools.message().empty()) ImGui::TextDisabled("%s", tools.message().c_str());
  ImGui::Separator();
  return moved;
}

}  // namespace sdfc::viewer
