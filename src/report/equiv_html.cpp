#include "report/equiv_html.h"

#include <fmt/format.h>

#include "motion/xml_text.h"

namespace gcx::report {

using motion::xmlEscape;

namespace {

constexpr double kNominalWidthPx = 1100; // the marker's scale before the script measures

constexpr const char* kStyle = R"(
body{font-family:sans-serif;margin:16px;color:#222;background:#fff}
h1{font-size:20px;margin:0 0 8px}
h2{font-size:15px;margin:0 0 4px}
.verdict{font-size:17px;font-weight:bold;margin:0 0 10px}
.verdict.equivalent{color:#1d7a1d}.verdict.different{color:#b00020}
table.summary{border-collapse:collapse;margin-bottom:10px;font-size:13px}
table.summary th,table.summary td{border:1px solid #ccc;padding:3px 8px;text-align:left}
.toolbar{margin:6px 0;font-size:13px}
.toolbar button{margin-right:6px}
.legend span{display:inline-block;margin-right:14px}
.swatch{display:inline-block;width:28px;height:0;vertical-align:middle;margin-right:4px}
#plot{width:100%;height:62vh;border:1px solid #bbb;background:#fff;cursor:grab;display:block}
#plot .grid line{vector-effect:non-scaling-stroke;stroke-width:1px}
#plot .axes line{vector-effect:non-scaling-stroke;stroke-width:1.5px}
.excerpts{display:flex;gap:12px;margin-top:12px}
.excerpt{flex:1;min-width:0}
.chain{font-size:12px;color:#555;margin:0 0 4px}
.code{font-family:monospace;font-size:12px;white-space:pre;overflow-x:auto;border:1px solid #ccc}
.row .ln{display:inline-block;width:5em;color:#888;text-align:right;padding-right:8px}
.row.hit{background:#fde2f3;font-weight:bold}
.row.caret{color:#d0109c}
)";

// Zoom with the wheel about the pointer, pan by dragging, "fit" and "zoom to divergence" (also
// on opening OUT.html#at-divergence); the marker keeps its size on screen.
constexpr const char* kScript = R"(
(function(){
var svg=document.getElementById('plot');
var home=svg.getAttribute('viewBox').split(' ').map(Number);
var vb=home.slice();
var marker=document.getElementById('divergence');
function toUser(x,y){var m=svg.getScreenCTM().inverse();return new DOMPoint(x,y).matrixTransform(m);}
function set(v){vb=v;svg.setAttribute('viewBox',v.join(' '));
 if(marker){var k=1/svg.getScreenCTM().a;marker.setAttribute('transform','translate('+marker.dataset.x+' '+marker.dataset.y+') scale('+k+')');}}
svg.addEventListener('wheel',function(e){e.preventDefault();var p=toUser(e.clientX,e.clientY);
 var f=e.deltaY<0?0.8:1.25;set([p.x-(p.x-vb[0])*f,p.y-(p.y-vb[1])*f,vb[2]*f,vb[3]*f]);},{passive:false});
var drag=null;
svg.addEventListener('pointerdown',function(e){drag=toUser(e.clientX,e.clientY);svg.setPointerCapture(e.pointerId);});
svg.addEventListener('pointermove',function(e){if(!drag)return;var p=toUser(e.clientX,e.clientY);
 set([vb[0]+drag.x-p.x,vb[1]+drag.y-p.y,vb[2],vb[3]]);});
svg.addEventListener('pointerup',function(){drag=null;});
document.getElementById('fit').addEventListener('click',function(){set(home.slice());});
var zd=document.getElementById('zoom-divergence');
if(zd)zd.addEventListener('click',function(){var x=+marker.dataset.x,y=+marker.dataset.y;
 var w=home[2]/20,h=home[3]/20;set([x-w/2,y-h/2,w,h]);});
window.addEventListener('resize',function(){set(vb);});
set(vb);
if(zd&&location.hash==='#at-divergence')zd.click();
})();
)";

std::string mm(double v, int decimals = 3) {
  return fmt::format("{:.{}f}", v, decimals);
}

std::string location(const SourceExcerpt& x) {
  if (x.line == 0) return "—";
  return xmlEscape(fmt::format("{}:{}:{}", x.file, x.line, x.column));
}

void excerptSection(std::string& s, const char* id, const EquivSide& side) {
  const SourceExcerpt& x = side.excerpt;
  s += fmt::format("<section class=\"excerpt\" id=\"{}\">\n<h2>{}: {}</h2>\n", id,
                   xmlEscape(side.name), x.line ? location(x) : xmlEscape(side.file));
  if (!x.chain.empty()) s += "<p class=\"chain\">" + xmlEscape(x.chain) + "</p>\n";
  s += "<div class=\"code\">";
  for (const ExcerptLine& l : x.lines) {
    const bool hit = l.number == x.line;
    s += fmt::format("<div class=\"row{}\"><span class=\"ln\">{}</span>{}</div>", hit ? " hit" : "",
                     l.number, xmlEscape(l.text));
    if (hit && x.column > 0)
      s += fmt::format("<div class=\"row caret\"><span class=\"ln\"></span>{}^</div>",
                       std::string(static_cast<std::size_t>(x.column - 1), ' '));
  }
  if (x.lines.empty()) s += "<div class=\"row\">(no source lines)</div>";
  s += "</div>\n</section>\n";
}

void summaryTable(std::string& s, const EquivPage& p) {
  s += "<table class=\"summary\">\n";
  s += fmt::format("<tr><th></th><th>{}</th><th>{}</th></tr>\n", xmlEscape(p.a.name),
                   xmlEscape(p.b.name));
  s += fmt::format("<tr><th>program</th><td>{}</td><td>{}</td></tr>\n", xmlEscape(p.a.file),
                   xmlEscape(p.b.file));
  // A difference stops the comparison: the figures then cover what was compared.
  const char* upTo = p.equivalent ? "" : ", up to the divergence";
  s += fmt::format("<tr><th>path length (mm{})</th><td>{}</td><td>{}</td></tr>\n", upTo,
                   mm(p.a.length), mm(p.b.length));
  s += fmt::format("<tr><th>time (s{})</th><td>{}</td><td>{}</td></tr>\n", upTo, mm(p.a.time, 2),
                   mm(p.b.time, 2));
  s += fmt::format("<tr><th>first divergence</th><td>{}</td><td>{}</td></tr>\n",
                   location(p.a.excerpt), location(p.b.excerpt));
  s += fmt::format("<tr><th>divergence point (machine)</th><td colspan=\"2\">{}</td></tr>\n",
                   p.divergence ? fmt::format("X{} Y{} Z{}", mm(p.divergence->x()),
                                              mm(p.divergence->y()), mm(p.divergence->z()))
                                : "—");
  s += fmt::format("<tr><th>max deviation before it (mm)</th><td colspan=\"2\">{}</td></tr>\n",
                   mm(p.maxDeviation, 4));
  s += fmt::format("<tr><th>tolerance (mm)</th><td colspan=\"2\">{}</td></tr>\n",
                   mm(p.tolerance, 4));
  s += "</table>\n";
}

void drawing(std::string& s, const EquivPage& p, const PathRecorder& a, const PathRecorder& b,
             motion::View view) {
  motion::Box2 box;
  const auto runsA = a.polylines(view), runsB = b.polylines(view);
  for (const auto* runs : {&runsA, &runsB})
    for (const motion::Polyline& r : *runs)
      for (const motion::Vec2& q : r.points)
        box.extend(q);
  if (p.divergence) box.extend(motion::project(view, *p.divergence));
  const motion::SvgCanvas c(view, box, 1e-3, 0.05, 0, true);

  s += "<div class=\"toolbar\"><button id=\"fit\" type=\"button\">Fit</button>";
  if (p.divergence)
    s += "<button id=\"zoom-divergence\" type=\"button\">Zoom to divergence</button>";
  s += fmt::format("<span class=\"legend\"><span><i class=\"swatch\" style=\"border-top:4px "
                   "solid {}\"></i>{}: {}</span><span><i class=\"swatch\" style=\"border-top:2px "
                   "solid {}\"></i>{}: {}</span><span><i class=\"swatch\" style=\"border-top:2px "
                   "dashed #666\"></i>rapid</span>",
                   kSideAColour, xmlEscape(p.a.name), xmlEscape(p.a.file), kSideBColour,
                   xmlEscape(p.b.name), xmlEscape(p.b.file));
  if (p.divergence)
    s += fmt::format("<span><i class=\"swatch\" style=\"border-top:3px solid {}\"></i>divergence"
                     "</span>",
                     kMarkerColour);
  s += fmt::format("</span> <span>view {}, machine frame; wheel: zoom, drag: pan</span></div>\n",
                   motion::viewName(view));

  s += fmt::format("<svg id=\"plot\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{}\" "
                   "preserveAspectRatio=\"xMidYMid meet\">\n",
                   c.viewBox());
  s += c.grid();
  // A drawn wide under B, so where they coincide both stay visible.
  const struct {
    const char* id;
    const char* colour;
    double width;
    const std::vector<motion::Polyline>& runs;
  } sides[] = {{"path-a", kSideAColour, 5, runsA}, {"path-b", kSideBColour, 2, runsB}};
  for (const auto& side : sides) {
    s += fmt::format("<g id=\"{}\" fill=\"none\" stroke-linecap=\"round\" "
                     "stroke-linejoin=\"round\">\n",
                     side.id);
    s += c.paths(side.runs, motion::PathStyle{"feed", side.colour, side.width, 0, 0, true},
                 motion::PathStyle{"rapid", side.colour, side.width / 2, 8, 5, true});
    s += "</g>\n";
  }
  if (p.divergence) {
    // Drawn in screen pixels about the point: the script rescales it with the zoom.
    const motion::Vec2 d = motion::project(view, *p.divergence);
    const double k = c.width() / kNominalWidthPx;
    s += fmt::format("<g id=\"divergence\" data-x=\"{0}\" data-y=\"{1}\" "
                     "transform=\"translate({0} {1}) scale({2})\" stroke=\"{3}\" fill=\"none\">\n",
                     c.num(d.x()), c.num(-d.y()), c.num(k), kMarkerColour);
    s += "<circle r=\"13\" stroke-width=\"4\"/>\n";
    s += "<path d=\"M-26 0H-15M15 0H26M0 -26V-15M0 15V26\" stroke-width=\"3\"/>\n";
    s += fmt::format("<text x=\"18\" y=\"-18\" fill=\"{}\" stroke=\"none\" font-size=\"15\" "
                     "font-weight=\"bold\">divergence</text>\n",
                     kMarkerColour);
    s += "</g>\n";
  }
  s += "</svg>\n";
}

} // namespace

motion::View defaultView(const PathRecorder& a, const PathRecorder& b) {
  for (const PathRecorder* r : {&a, &b})
    if (!r->bounds().isEmpty() && r->bounds().sizes().y() > 1e-9) return motion::View::XY;
  const bool any = !a.bounds().isEmpty() || !b.bounds().isEmpty();
  return any ? motion::View::XZ : motion::View::XY;
}

void writeEquivHtml(std::ostream& out, const EquivPage& page, const PathRecorder& a,
                    const PathRecorder& b, motion::View view) {
  std::string s;
  s += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  s += fmt::format("<title>gcx equiv: {} vs {}</title>\n", xmlEscape(page.a.file),
                   xmlEscape(page.b.file));
  s += fmt::format("<style>{}</style>\n</head>\n<body>\n", kStyle);
  s +=
      fmt::format("<h1>gcx equiv: {} vs {}</h1>\n", xmlEscape(page.a.file), xmlEscape(page.b.file));
  s += fmt::format("<p class=\"verdict {}\">{}: {}</p>\n",
                   page.equivalent ? "equivalent" : "different",
                   page.equivalent ? "Equivalent" : "Different", xmlEscape(page.summary));
  summaryTable(s, page);
  drawing(s, page, a, b, view);
  s += "<div class=\"excerpts\">\n";
  excerptSection(s, "excerpt-a", page.a);
  excerptSection(s, "excerpt-b", page.b);
  s += "</div>\n";
  s += fmt::format("<script>{}</script>\n</body>\n</html>\n", kScript);
  out.write(s.data(), static_cast<std::streamsize>(s.size()));
}

} // namespace gcx::report
