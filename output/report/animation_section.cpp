#include "output/report/animation_section.h"

#include "output/report/base64.h"

namespace sled::report {

std::string AnimationSection(const std::string& glb) {
  std::string html = "<section id=\"animation\"><h2>Animation</h2>";
  if (glb.empty()) {
    return html +
           "<p class=\"note\" id=\"viewer-status\" data-state=\"absent\">The run folder has no "
           "animation.glb.</p></section>";
  }
  html +=
      "<div class=\"viewer\"><canvas id=\"viewer-canvas\" width=\"960\" height=\"540\"></canvas>"
      "<div class=\"controls\"><button type=\"button\" id=\"viewer-play\">play</button>"
      "<input type=\"range\" id=\"viewer-time\" min=\"0\" max=\"1000\" value=\"0\" "
      "aria-label=\"time\"><span id=\"viewer-clock\">0 ms</span>"
      "<label>speed <select id=\"viewer-speed\"><option value=\"0.01\">1/100</option>"
      "<option value=\"0.05\" selected>1/20</option><option value=\"0.2\">1/5</option>"
      "<option value=\"1\">real time</option></select></label>"
      "<button type=\"button\" id=\"viewer-reset\">reset view</button></div>"
      "<p class=\"note\">Drag to turn the view, scroll to zoom, shift-drag to pan.</p>"
      "<p class=\"note\" id=\"viewer-status\" data-state=\"loading\">Loading the animation…</p>"
      "</div>";
  // Base64 holds no `<`, so it cannot end the element early; the type keeps it from running.
  html += "<script type=\"application/octet-stream\" id=\"animation-glb\">";
  html += Base64(glb);
  html += "</script></section>";
  return html;
}

}  // namespace sled::report
