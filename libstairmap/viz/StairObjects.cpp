// Staircase-related objects of the viewer scene: landmarks and the detector's internals.
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CText.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>

#include "viz/ViewPicking.h"
#include "viz/ViewerScene.h"

namespace stairmap::viz {
namespace {

using mrpt::opengl::CSetOfLines;
using mrpt::opengl::CSetOfObjects;

CSetOfLines::Ptr lineSet(float width, unsigned char r, unsigned char g, unsigned char b) {
    auto lines = CSetOfLines::Create();
    lines->setLineWidth(width);
    lines->setColor_u8(r, g, b);
    return lines;
}

void appendSegment(CSetOfLines& lines, const LineSegment& l) {
    lines.appendLine(l.start.x(), l.start.y(), l.z, l.end.x(), l.end.y(), l.z);
}

void appendEdge(CSetOfLines& lines, const StairEdge& e) {
    lines.appendLine(e.start.x(), e.start.y(), e.start.z(), e.end.x(), e.end.y(), e.end.z());
}

mrpt::opengl::CText::Ptr label(std::string text, const Eigen::Vector3d& at,
                               unsigned char r, unsigned char g, unsigned char b) {
    // CText's font has no degree sign: "14°" -> "14 deg".
    for (auto pos = text.find("\u00b0"); pos != std::string::npos; pos = text.find("\u00b0"))
        text.replace(pos, std::string("\u00b0").size(), " deg");
    auto t = mrpt::opengl::CText::Create(text);
    t->setLocation(at.x(), at.y(), at.z());
    t->setColor_u8(r, g, b);
    return t;
}

/// Top-view nosing candidates: front drops (ascending) magenta, back drops (descending) cyan.
mrpt::opengl::CPointCloudColoured::Ptr candidateCloud(const DetectorDebug& d) {
    auto cloud = mrpt::opengl::CPointCloudColoured::Create();
    cloud->setPointSize(3.0f);
    for (const TopViewCell& c : d.candidates) {
        const bool front = (c.flags & kFrontDrop) != 0;
        cloud->push_back(c.x, c.y, c.z, front ? 1.0f : 0.2f, front ? 0.2f : 0.9f, 1.0f);
    }
    return cloud;
}

/// [-] rejected chains labelled with their reason (the others are drawn unlabelled): chains
/// refused for their length first, then the pairs nearest to the robot
constexpr std::size_t kMaxLabels = 8;

std::vector<const RejectedChain*> labelledChains(const DetectorDebug& d) {
    std::vector<const RejectedChain*> chains;
    for (const auto& c : d.rejected) chains.push_back(&c);
    const auto rank = [](const RejectedChain* c) {
        const bool length_rule = c->reason.find("steps <") != std::string::npos;
        return (length_rule ? 0.0 : 1000.0) + c->edges.front().centre().norm();
    };
    std::sort(chains.begin(), chains.end(),
              [&](const RejectedChain* a, const RejectedChain* b) { return rank(a) < rank(b); });
    if (chains.size() > kMaxLabels) chains.resize(kMaxLabels);
    return chains;
}

void addInternals(const DetectorDebug& d, CSetOfObjects& out) {
    out.insert(candidateCloud(d));
    auto rows = lineSet(1.5f, 200, 200, 200);  // every row's line segments
    for (const auto& l : d.lines_ascending) appendSegment(*rows, l);
    for (const auto& l : d.lines_descending) appendSegment(*rows, l);
    out.insert(rows);
    auto accepted = lineSet(4.0f, 60, 120, 255);
    for (const auto& s : d.accepted)
        for (const auto& e : s.steps) appendEdge(*accepted, e);
    out.insert(accepted);
    auto rejected = lineSet(3.0f, 255, 50, 50);
    for (const RejectedChain& c : d.rejected) {
        for (const auto& e : c.edges) appendSegment(*rejected, e);
        for (std::size_t i = 1; i < c.edges.size(); ++i) {  // join consecutive edges' centres
            const auto a = c.edges[i - 1].centre(), b = c.edges[i].centre();
            rejected->appendLine(a.x(), a.y(), c.edges[i - 1].z, b.x(), b.y(), c.edges[i].z);
        }
    }
    out.insert(rejected);
    for (const RejectedChain* c : labelledChains(d)) {
        const auto& top = c->edges.back();
        out.insert(label(c->reason, {top.centre().x(), top.centre().y(), top.z + 0.1}, 255, 90, 90));
    }
}

}  // namespace

CSetOfObjects::Ptr detectorObjects(const DetectorView& run, bool internals, bool box) {
    auto out = CSetOfObjects::Create();
    out->setPose(mrptPose(run.T_world_grav));
    if (box && run.radius_m > 0) {
        const double r = run.radius_m;
        const double floor_z = run.debug ? run.debug->floor_z : -0.5;
        // The submap's square footprint at the floor and 2 m above it, with vertical corners.
        auto b = lineSet(1.5f, 255, 230, 0);
        const double corners[4][2] = {{-r, -r}, {r, -r}, {r, r}, {-r, r}};
        for (int i = 0; i < 4; ++i) {
            const auto* p = corners[i];
            const auto* q = corners[(i + 1) % 4];
            for (double z : {floor_z, floor_z + 2.0}) b->appendLine(p[0], p[1], z, q[0], q[1], z);
            b->appendLine(p[0], p[1], floor_z, p[0], p[1], floor_z + 2.0);
        }
        out->insert(b);
    }
    if (internals && run.debug != nullptr) addInternals(*run.debug, *out);
    return out;
}

CSetOfObjects::Ptr landmarkObjects(const std::vector<StaircaseLandmark>& landmarks,
                                   int selected_id) {
    auto out = CSetOfObjects::Create();
    for (const StaircaseLandmark& lm : landmarks) {
        const unsigned char* rgb = lm.confirmed ? kConfirmedRgb : kTentativeRgb;
        const bool selected = lm.id == selected_id;
        auto edges = lineSet(selected ? 8.0f : 5.0f, rgb[0], rgb[1], rgb[2]);
        const Staircase& s = lm.stairs;
        const double depth = s.step_depth > 0 ? s.step_depth : kDrawnTreadDepthM;
        for (const StairEdge& e : s.steps) {
            appendEdge(*edges, e);
            // The tread behind the nosing, one run deep, thin and translucent.
            const double half = 0.5 * e.length();
            auto tread = mrpt::opengl::CBox::Create(mrpt::math::TPoint3D(0, -half, -0.02),
                                                    mrpt::math::TPoint3D(depth, half, 0));
            const Eigen::Vector3d c = e.centre();
            const double ahead = s.direction == StairDirection::Ascending ? 0.0 : M_PI;
            tread->setPose(mrpt::poses::CPose3D(c.x(), c.y(), c.z(), s.heading_rad + ahead, 0, 0));
            tread->setColor_u8(rgb[0], rgb[1], rgb[2], selected ? 230 : 150);
            out->insert(tread);
        }
        out->insert(edges);
        // The ID high above the top step (clear of nearby walls), tied to it by a leader line.
        const Eigen::Vector3d top = s.steps.empty() ? s.location : s.steps.back().centre();
        const Eigen::Vector3d tag = top + Eigen::Vector3d(0, 0, 1.2);
        auto leader = lineSet(2.0f, 255, 255, 255);
        leader->appendLine(top.x(), top.y(), top.z(), tag.x(), tag.y(), tag.z());
        out->insert(leader);
        const std::string text = "#" + std::to_string(lm.id) + (selected ? " *" : "");
        out->insert(label(text, tag, 255, 255, 255));
    }
    return out;
}

}  // namespace stairmap::viz
