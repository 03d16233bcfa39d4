#include "viewer/ViewerScript.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace stairmap::viewer {
namespace {

const char* const kNoArg[] = {"play",   "pause",       "toggle-play", "restart", "faster",
                              "slower", "select-next", "camera-next", "wait-end", "quit"};
const char* const kWithArg[] = {"seek", "speed", "toggle", "show", "hide", "camera", "wait"};
const char* const kOptionalArg[] = {"step", "back"};

bool among(const std::string& verb, const char* const* list, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        if (verb == list[i]) return true;
    return false;
}

double number(const ScriptAction& a) {
    try {
        std::size_t used = 0;
        const double v = std::stod(a.arg, &used);
        if (used == a.arg.size() && v >= 0) return v;
    } catch (const std::exception&) {
    }
    throw std::invalid_argument(a.verb + ": '" + a.arg + "' is not a number >= 0");
}

Layer layerOf(const ScriptAction& a) {
    Layer layer;
    if (!parseLayer(a.arg, layer)) throw std::invalid_argument(a.verb + ": unknown layer '" + a.arg + "'");
    return layer;
}

void applySpeed(ViewerState& s, double speed) {
    for (int i = 0; i < kNumSpeeds; ++i) {
        if (kSpeeds[i] == speed) return s.setSpeedIndex(i);
    }
    throw std::invalid_argument("speed: " + std::to_string(speed) + " is not one of 0.25 0.5 1 2 4 8");
}

}  // namespace

ScriptAction parseAction(const std::string& text, int line) {
    std::istringstream in(text.substr(0, text.find('#')));
    ScriptAction a;
    a.line = line;
    in >> a.verb >> a.arg;
    std::string extra;
    if (in >> extra) throw std::invalid_argument("too many words");
    const bool no_arg = among(a.verb, kNoArg, std::size(kNoArg));
    const bool with_arg = among(a.verb, kWithArg, std::size(kWithArg));
    const bool optional = among(a.verb, kOptionalArg, std::size(kOptionalArg));
    if (!no_arg && !with_arg && !optional) throw std::invalid_argument("unknown action '" + a.verb + "'");
    if (no_arg && !a.arg.empty()) throw std::invalid_argument(a.verb + " takes no argument");
    if (with_arg && a.arg.empty()) throw std::invalid_argument(a.verb + " needs an argument");
    if (a.verb == "camera" && !viz::parseCameraMode(a.arg))
        throw std::invalid_argument("camera: '" + a.arg + "' is not follow, top or orbit");
    if (a.verb == "toggle" || a.verb == "show" || a.verb == "hide") layerOf(a);
    if (a.verb == "seek" || a.verb == "speed" || a.verb == "wait" || (optional && !a.arg.empty()))
        number(a);
    return a;
}

std::vector<ScriptAction> loadScript(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open the script");
    std::vector<ScriptAction> actions;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        if (text.find_first_not_of(" \t\r") == std::string::npos || text[text.find_first_not_of(" \t")] == '#')
            continue;
        try {
            actions.push_back(parseAction(text, line));
        } catch (const std::invalid_argument& e) {
            throw std::runtime_error(path + ":" + std::to_string(line) + ": " + e.what());
        }
    }
    return actions;
}

void applyAction(const ScriptAction& a, ViewerController& c) {
    ViewerState& s = c.state();
    const auto count = [&a] { return a.arg.empty() ? 1 : static_cast<int>(number(a)); };
    if (a.verb == "play") s.play();
    else if (a.verb == "pause") s.pause();
    else if (a.verb == "toggle-play") s.togglePlay();
    else if (a.verb == "step") for (int i = count(); i > 0; --i) s.stepForward();
    else if (a.verb == "back") for (int i = count(); i > 0; --i) s.stepBack();
    else if (a.verb == "seek") s.seek(static_cast<std::size_t>(number(a)));
    else if (a.verb == "restart") s.restart();
    else if (a.verb == "faster") s.faster();
    else if (a.verb == "slower") s.slower();
    else if (a.verb == "speed") applySpeed(s, number(a));
    else if (a.verb == "toggle") s.toggle(layerOf(a));
    else if (a.verb == "show") s.setShown(layerOf(a), true);
    else if (a.verb == "hide") s.setShown(layerOf(a), false);
    else if (a.verb == "select-next") c.selectNextLandmark();
    else if (a.verb == "camera") s.setCamera(*viz::parseCameraMode(a.arg));
    else if (a.verb == "camera-next") s.cycleCamera();
}

bool ScriptRunner::update(ViewerController& controller, double now_s) {
    if (waiting_end_ && controller.state().playing()) return true;
    waiting_end_ = false;
    if (now_s < hold_until_s_) return true;
    while (next_ < actions_.size()) {
        const ScriptAction& a = actions_[next_++];
        if (a.verb == "quit") return false;
        if (a.verb == "wait") {
            hold_until_s_ = now_s + number(a);
            return true;  // let the window draw meanwhile
        }
        if (a.verb == "wait-end") {
            waiting_end_ = true;
            return true;
        }
        applyAction(a, controller);
    }
    return false;
}

}  // namespace stairmap::viewer
