#include "motion/trace_writer.h"

#include <gtest/gtest.h>
#include <sstream>

#include "motion/decimal.h"
#include "motion/event_builders.h"

namespace gcx::motion {
namespace {

using namespace test;

std::string fileName(FileId f) {
  return f == 0 ? "main.nct" : "O9010.nct";
}

TEST(Decimal, AtMostSixDecimalsNoExponent) {
  EXPECT_EQ(formatDecimal(0), "0");
  EXPECT_EQ(formatDecimal(-0.0), "0");
  EXPECT_EQ(formatDecimal(1.0 / 3), "0.333333");
  EXPECT_EQ(formatDecimal(-2.5), "-2.5");
  EXPECT_EQ(formatDecimal(1e-7), "0");
  EXPECT_EQ(formatDecimal(-4e-7), "0");
  EXPECT_EQ(formatDecimal(0.0000006), "0.000001");
  EXPECT_EQ(formatDecimal(0.0000005), "0"); // rounds the binary value, just below 5e-7
  EXPECT_EQ(formatDecimal(1e20), "100000000000000000000");
  EXPECT_EQ(formatDecimal(12.5, 0), "12");
  EXPECT_EQ(formatDecimal(std::numeric_limits<double>::quiet_NaN()), "null");
}

TEST(TraceWriter, LineEvent) {
  std::ostringstream out;
  TraceWriter w(out, fileName);
  Event e = feed({0, 0, 0}, {10.5, -2, 1.0 / 3}, 500);
  e.from.at = SourceLoc{0, 3, 1, 40};
  w.event(e);
  EXPECT_EQ(out.str(), "{\"kind\":\"feed\",\"start\":[0,0,0],\"end\":[10.5,-2,0.333333],"
                       "\"feed\":500,\"at\":\"main.nct:3:1\"}\n");
}

TEST(TraceWriter, ArcEventWithCallChain) {
  std::ostringstream out;
  TraceWriter w(out, fileName);
  Event e = arc(Plane::XY, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, false, 0, 200);
  e.from.at = SourceLoc{1, 4, 1, 0};
  e.from.chain = {Frame{SourceLoc{0, 12, 5, 0}, "O9010"}};
  w.event(e);
  EXPECT_EQ(out.str(), "{\"kind\":\"arc\",\"start\":[10,0,0],\"end\":[0,10,0],\"center\":[0,0,0],"
                       "\"plane\":\"XY\",\"dir\":\"ccw\",\"turns\":0,\"feed\":200,"
                       "\"at\":\"O9010.nct:4:1\","
                       "\"chain\":[{\"what\":\"O9010\",\"at\":\"main.nct:12:5\"}]}\n");
}

TEST(TraceWriter, SampleModeWritesPoints) {
  std::ostringstream out;
  TraceWriter w(out, {}, TraceOptions{true, 1.0});
  Event e = arc(Plane::XY, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, false, 0, 200);
  e.from.at = SourceLoc{0, 4, 1, 0};
  w.event(e);
  // tolerance 1 on radius 10: two segments for a quarter
  EXPECT_EQ(out.str(), "{\"kind\":\"arc\",\"start\":[10,0,0],\"end\":[0,10,0],"
                       "\"points\":[[10,0,0],[7.071068,7.071068,0],[0,10,0]],"
                       "\"feed\":200,\"at\":\"#0:4:1\"}\n");
}

TEST(TraceWriter, OtherKinds) {
  std::ostringstream out;
  TraceWriter w(out, fileName);
  Event sp = valueEvent(Kind::Spindle, 1200);
  sp.direction = -1;
  Event stop;
  stop.kind = Kind::Stop;
  stop.optional = true;
  Event msg;
  msg.kind = Kind::Message;
  msg.text = "say \"hi\"\n";
  Event perRevFeed = feed({0, 0, 0}, {1, 0, 0}, 0.25);
  perRevFeed.perRevolution = true;
  EXPECT_EQ(w.line(valueEvent(Kind::Dwell, 2)), "{\"kind\":\"dwell\",\"seconds\":2}");
  EXPECT_EQ(w.line(valueEvent(Kind::Dwell, 3, true)), "{\"kind\":\"dwell\",\"revolutions\":3}");
  EXPECT_EQ(w.line(sp), "{\"kind\":\"spindle\",\"speed\":1200,\"dir\":\"ccw\"}");
  EXPECT_EQ(w.line(valueEvent(Kind::ToolChange, 7)), "{\"kind\":\"tool_change\",\"tool\":7}");
  EXPECT_EQ(w.line(valueEvent(Kind::Coolant, 8)), "{\"kind\":\"coolant\",\"code\":8}");
  EXPECT_EQ(w.line(stop), "{\"kind\":\"stop\",\"optional\":true}");
  EXPECT_EQ(w.line(msg), "{\"kind\":\"message\",\"text\":\"say \\\"hi\\\"\\n\"}");
  EXPECT_EQ(w.line(rapid({1, 2, 3}, {4, 5, 6})),
            "{\"kind\":\"rapid\",\"start\":[1,2,3],\"end\":[4,5,6]}");
  EXPECT_EQ(w.line(perRevFeed),
            "{\"kind\":\"feed\",\"start\":[0,0,0],\"end\":[1,0,0],\"feed\":0.25,\"per_rev\":true}");
  Event end;
  end.kind = Kind::End;
  EXPECT_EQ(w.line(end), "{\"kind\":\"end\"}");
}

TEST(TraceWriter, ExtraAxesOnlyWhenOffZero) {
  std::ostringstream out;
  TraceWriter w(out);
  // all zero: the line is the same as without extra axes
  EXPECT_EQ(w.line(withExtra(feed({0, 0, 0}, {1, 0, 0}, 100), Extra::Zero(), Extra::Zero())),
            "{\"kind\":\"feed\",\"start\":[0,0,0],\"end\":[1,0,0],\"feed\":100}");
  EXPECT_EQ(w.line(withExtra(feed({1, 0, 0}, {1, 0, 0}, 720), Extra::Zero(), extra(90, 0, 0))),
            "{\"kind\":\"feed\",\"start\":[1,0,0],\"end\":[1,0,0],"
            "\"extra_start\":{\"A\":0},\"extra_end\":{\"A\":90},\"feed\":720}");
  // the axes off zero at either end, both objects alike, U V W after A B C
  EXPECT_EQ(w.line(withExtra(rapid({1, 0, 0}, {2, 0, 0}), extra(90, 0, 0, 0, 0, 2.5),
                             extra(0, 0, 1.0 / 3, 0, 0, 2.5))),
            "{\"kind\":\"rapid\",\"start\":[1,0,0],\"end\":[2,0,0],"
            "\"extra_start\":{\"A\":90,\"C\":0,\"W\":2.5},"
            "\"extra_end\":{\"A\":0,\"C\":0.333333,\"W\":2.5}}");
  // arcs: after the end, before the arc's own keys
  EXPECT_EQ(w.line(withExtra(arc(Plane::XY, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, true),
                             extra(0, 5, 0), extra(0, -5, 0))),
            "{\"kind\":\"arc\",\"start\":[10,0,0],\"end\":[0,10,0],"
            "\"extra_start\":{\"B\":5},\"extra_end\":{\"B\":-5},\"center\":[0,0,0],"
            "\"plane\":\"XY\",\"dir\":\"cw\",\"turns\":0,\"feed\":100}");
  // non-motion events carry the position but do not write it
  Event dwell = withExtra(valueEvent(Kind::Dwell, 1), extra(45, 0, 0), extra(45, 0, 0));
  EXPECT_EQ(w.line(dwell), "{\"kind\":\"dwell\",\"seconds\":1}");
}

TEST(TraceWriter, ModalChanges) {
  std::ostringstream out;
  TraceWriter w(out, fileName);
  Event zx = valueEvent(Kind::PlaneChange, 0);
  zx.plane = Plane::ZX;
  zx.from.at = SourceLoc{0, 5, 1, 0};
  Event uv = valueEvent(Kind::PlaneChange, 0);
  uv.text = "UV";
  EXPECT_EQ(w.line(zx), "{\"kind\":\"plane\",\"plane\":\"ZX\",\"at\":\"main.nct:5:1\"}");
  EXPECT_EQ(w.line(uv), "{\"kind\":\"plane\",\"plane\":\"XY\",\"axes\":\"UV\"}");
  EXPECT_EQ(w.line(valueEvent(Kind::UnitsChange, 20)), "{\"kind\":\"units\",\"code\":20}");
  EXPECT_EQ(w.line(valueEvent(Kind::FeedModeChange, 95)), "{\"kind\":\"feed_mode\",\"code\":95}");
  EXPECT_STREQ(kindName(Kind::FeedModeChange), "feed_mode");
}

} // namespace
} // namespace gcx::motion
