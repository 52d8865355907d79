// The text form of cycle ops used by the test vectors (cycles.md §1.1, §8).
#include <cmath>

#include "cycles/ops.h"
#include "emit/number.h"

namespace gcx::cycles {

namespace {

double round4(double v) {
  return std::round(v * 1e4) / 1e4;
}

void number(std::string& out, char letter, double v) {
  out += ' ';
  out += letter;
  emit::appendNumber(out, round4(v));
}

const char* code(OpKind k) {
  switch (k) {
  case OpKind::Rapid:
    return "G0";
  case OpKind::Feed:
    return "G1";
  case OpKind::ArcCW:
    return "G2";
  case OpKind::ArcCCW:
    return "G3";
  case OpKind::Thread:
    return "G33";
  case OpKind::RigidTap:
    return "RTAP";
  case OpKind::SpindleCW:
    return "M3";
  case OpKind::SpindleCCW:
    return "M4";
  case OpKind::SpindleStop:
    return "M5";
  case OpKind::SpindleOrient:
    return "M19";
  case OpKind::ProgramStop:
    return "M0";
  case OpKind::OverrideLock:
    return "G63";
  case OpKind::OverrideRestore:
    return "G64";
  default:
    return "";
  }
}

bool isMove(OpKind k) {
  return k == OpKind::Rapid || k == OpKind::Feed || k == OpKind::ArcCW || k == OpKind::ArcCCW ||
         k == OpKind::Thread || k == OpKind::RigidTap;
}

} // namespace

std::string opsText(const Vec3& start, const std::vector<CycleOp>& ops, std::string_view axes,
                    unsigned diameter) {
  std::string out;
  Vec3 at = start;
  auto shown = [&](const Vec3& p, int a) { return (diameter >> a) & 1u ? 2 * p[a] : p[a]; };
  for (const CycleOp& o : ops) {
    if (!out.empty()) out += " | ";
    if (!isMove(o.kind)) {
      if (o.kind == OpKind::Dwell) {
        out += "G4";
        number(out, 'P', o.value);
      } else if (o.kind == OpKind::CloseLoop) {
        out += 'M';
        emit::appendNumber(out, o.value);
      } else {
        out += code(o.kind);
      }
      continue;
    }
    out += code(o.kind);
    for (int a = 0; a < 3; ++a)
      if (round4(shown(o.to, a)) != round4(shown(at, a))) number(out, axes[a], shown(o.to, a));
    if (o.kind == OpKind::ArcCW || o.kind == OpKind::ArcCCW)
      number(out, 'R', (o.to - o.center).norm());
    at = o.to;
    if (o.kind == OpKind::Thread) number(out, 'F', o.value);
    if (o.kind != OpKind::Rapid && o.kind != OpKind::Thread) number(out, 'F', o.feed);
    if (o.kind == OpKind::RigidTap) {
      number(out, 'S', o.value);
      out += o.direction > 0 ? " DIR=CW" : " DIR=CCW";
      if (o.override != 100) {
        out += " OVR=";
        emit::appendNumber(out, round4(o.override));
        out += '%';
      }
    }
  }
  return out;
}

} // namespace gcx::cycles
