#include "replay_script.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "world/error.hpp"
#include "world/file_read.hpp"

namespace onelight::replay {

namespace {

std::vector<std::string_view> splitWords(std::string_view line) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

class LineParser {
public:
    LineParser(const std::string& path, int line, std::vector<std::string_view> words)
        : path_(path), line_(line), words_(std::move(words)) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw ScriptError(path_ + ":" + std::to_string(line_) + ": " + what);
    }
    bool done() const { return next_ >= words_.size(); }
    std::string_view word(const char* expected) {
        if (done()) fail(std::string("expected ") + expected + " at the end of the line");
        return words_[next_++];
    }
    void keyword(std::string_view k) {
        std::string_view w = word(std::string(k).c_str());
        if (w != k) fail("expected '" + std::string(k) + "', found '" + quoted(w) + "'");
    }
    double number(const char* expected) {
        std::string_view w = word(expected);
        std::string_view digits = w.size() > 1 && w[0] == '+' ? w.substr(1) : w;
        double x = 0.0;
        auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), x);
        if (ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(x))
            fail(std::string("expected ") + expected + " (a number), found '" + quoted(w) + "'");
        return x;
    }
    // A number in [-limit, limit].
    double bounded(const char* expected, double limit) {
        const double x = number(expected);
        if (!(std::fabs(x) <= limit)) {
            char text[160];
            std::snprintf(text, sizeof text, "expected %s from %g to %g, found %g", expected,
                          -limit, limit, x);
            fail(text);
        }
        return x;
    }
    static std::string quoted(std::string_view w) { return world::clipForMessage(w, 60); }
    bool choice(std::string_view yes, std::string_view no) {
        std::string_view w = word((std::string(yes) + " or " + std::string(no)).c_str());
        if (w == yes) return true;
        if (w == no) return false;
        fail("expected '" + std::string(yes) + "' or '" + std::string(no) + "', found '" +
             quoted(w) + "'");
    }
    void end() {
        if (!done()) fail("unexpected '" + quoted(words_[next_]) + "' after the command");
    }

private:
    const std::string& path_;
    int line_;
    std::vector<std::string_view> words_;
    size_t next_ = 0;
};

const std::set<std::string_view>& knownKeys() {
    static const std::set<std::string_view> keys = {"W", "A", "S", "D", "SPACE", "SHIFT", "CTRL",
                                                    "F", "E", "Q", "R", "0",     "1",     "2",
                                                    "3", "4", "5", "6", "7",     "8",     "9"};
    return keys;
}

constexpr const char* kPlayerChecks =
    "on-ground, in-air, moved, feet, height, velocity, teleports, launches, respawns or riding";

}  // namespace

Script parseScript(std::string_view text, const std::string& path) {
    Script script;
    script.path = path;
    double cursor = 0.0;     // seconds
    bool timedSeen = false;  // header commands must precede timed ones
    int lineNumber = 0;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view raw = text.substr(start, end - start);
        start = end + 1;
        ++lineNumber;
        if (size_t hash = raw.find('#'); hash != std::string_view::npos) raw = raw.substr(0, hash);
        std::vector<std::string_view> words = splitWords(raw);
        if (words.empty()) continue;
        LineParser p(path, lineNumber, words);
        std::string_view head = p.word("a command");

        if (head == "level" || head == "tick") {
            if (timedSeen) p.fail("'" + std::string(head) + "' must come before any timed command");
            if (head == "level") {
                if (!script.level.empty()) p.fail("the level is already named");
                script.level = std::string(p.word("a level name"));
            } else {
                script.tickRate = p.number("a tick rate in Hz");
                if (script.tickRate < 1.0 || script.tickRate > 1000.0)
                    p.fail("expected a tick rate between 1 and 1000 Hz");
            }
            p.end();
            continue;
        }
        if (head == "wait") {
            double s = p.number("seconds");
            if (s < 0.0) p.fail("expected a wait of zero or more seconds");
            if (cursor + s > kMaxScriptSeconds) {
                char buf[128];
                std::snprintf(buf, sizeof buf,
                              "the wait reaches %g s; expected a script of at most %g s",
                              cursor + s, kMaxScriptSeconds);
                p.fail(buf);
            }
            cursor += s;
            p.end();
            continue;
        }
        if (head == "at") {
            double t = p.number("a time in seconds");
            if (t < 0.0) p.fail("expected a time of zero or more seconds");
            if (t > kMaxScriptSeconds) {
                char buf[128];
                std::snprintf(buf, sizeof buf, "time %g s; expected at most %g s (a day)", t,
                              kMaxScriptSeconds);
                p.fail(buf);
            }
            if (t < cursor) {
                char buf[96];
                std::snprintf(buf, sizeof buf,
                              "time %g goes backwards (the previous command is at %g)", t, cursor);
                p.fail(buf);
            }
            cursor = t;
            head = p.word("a command after the time");
        }

        Command c;
        c.line = lineNumber;
        c.time = cursor;
        c.tick = uint64_t(std::llround(cursor * script.tickRate));
        if (head == "spawn") {
            c.kind = CommandKind::kSpawn;
            c.name = std::string(p.word("'player'"));
            if (c.name != "player")
                p.fail("expected 'player', found '" + LineParser::quoted(c.name) + "'");
            for (int i = 0; i < 3; ++i)
                c.values[i] = float(p.bounded("a coordinate in metres", kMaxScriptCoordinate));
            p.keyword("yaw");
            c.values[3] = float(p.bounded("a yaw in degrees", kMaxScriptDegrees));
            p.keyword("pitch");
            c.values[4] = float(p.bounded("a pitch in degrees", kMaxScriptDegrees));
        } else if (head == "key") {
            c.kind = CommandKind::kKey;
            c.name = std::string(p.word("a key name"));
            if (!knownKeys().count(c.name))
                p.fail("expected a key (W A S D SPACE SHIFT CTRL F E Q R 0-9), found '" +
                       LineParser::quoted(c.name) + "'");
            c.on = p.choice("down", "up");
        } else if (head == "look") {
            c.kind = CommandKind::kLook;
            c.values[0] = float(p.bounded("a yaw change in degrees", kMaxScriptDegrees));
            c.values[1] = float(p.bounded("a pitch change in degrees", kMaxScriptDegrees));
        } else if (head == "flashlight") {
            c.kind = CommandKind::kFlashlight;
            c.on = p.choice("on", "off");
        } else if (head == "fire") {
            c.kind = CommandKind::kFire;
        } else if (head == "capture") {
            c.kind = CommandKind::kCapture;
            c.name = std::string(p.word("a capture name"));
            if (c.name.find('/') != std::string::npos || c.name.find("..") != std::string::npos)
                p.fail("expected a capture name without '/' or '..', found '" +
                       LineParser::quoted(c.name) + "'");
        } else if (head == "expect") {
            std::string_view what =
                p.word("'primary', 'effect-lights', 'player', 'item' or 'mover'");
            if (what == "primary") {
                c.kind = CommandKind::kExpectPrimary;
                c.name = std::string(p.word("an entity name"));
                p.keyword("==");
                c.light = std::string(p.word("a light name"));
            } else if (what == "effect-lights") {
                c.kind = CommandKind::kExpectEffectLights;
                double n = p.number("a count of effect lights");
                if (n < 0 || n > 5 || n != std::floor(n))
                    p.fail("expected a whole count from 0 to 5");
                c.count = int(n);
            } else if (what == "player") {
                const std::string_view check = p.word(kPlayerChecks);
                if (check == "on-ground") {
                    c.kind = CommandKind::kExpectOnGround;
                } else if (check == "in-air") {
                    c.kind = CommandKind::kExpectInAir;
                } else if (check == "moved") {
                    c.kind = CommandKind::kExpectMoved;
                    double d = p.number("a distance in metres");
                    if (!(d >= 0.0 && d <= 1e6)) p.fail("expected a distance from 0 to 1e6 metres");
                    c.values[0] = float(d);
                } else if (check == "feet" || check == "velocity") {
                    c.kind =
                        check == "feet" ? CommandKind::kExpectFeet : CommandKind::kExpectVelocity;
                    const char* what3 =
                        check == "feet" ? "a coordinate in metres" : "a speed in m/s";
                    for (int i = 0; i < 3; ++i)
                        c.values[i] = float(p.bounded(what3, kMaxScriptCoordinate));
                    p.keyword("within");
                    const double d = p.bounded("a tolerance", kMaxScriptCoordinate);
                    if (!(d >= 0.0)) p.fail("expected a tolerance of zero or more");
                    c.values[3] = float(d);
                } else if (check == "height") {
                    c.kind = CommandKind::kExpectHeight;
                    c.values[0] =
                        float(p.bounded("a lowest height in metres", kMaxScriptCoordinate));
                    c.values[1] =
                        float(p.bounded("a highest height in metres", kMaxScriptCoordinate));
                    if (!(c.values[0] <= c.values[1]))
                        p.fail("expected the lowest height first (MIN <= MAX)");
                } else if (check == "riding") {
                    c.kind = CommandKind::kExpectRiding;
                    c.name = std::string(p.word("a mover's name"));
                } else if (check == "teleports" || check == "launches" || check == "respawns") {
                    c.kind = check == "teleports"  ? CommandKind::kExpectTeleports
                             : check == "launches" ? CommandKind::kExpectLaunches
                                                   : CommandKind::kExpectRespawns;
                    const double n = p.number("a count");
                    if (n < 0 || n > 1e6 || n != std::floor(n))
                        p.fail("expected a whole count from 0 to 1000000");
                    c.count = int(n);
                } else {
                    p.fail(std::string("expected ") + kPlayerChecks +
                           " after 'expect player', found '" + LineParser::quoted(check) + "'");
                }
            } else if (what == "item") {
                c.kind = CommandKind::kExpectItem;
                c.name = std::string(p.word("an item's name"));
                const std::string_view state = p.word("'visible' or 'taken'");
                if (state != "visible" && state != "taken")
                    p.fail("expected 'visible' or 'taken' after the item's name, found '" +
                           LineParser::quoted(state) + "'");
                c.on = state == "visible";
            } else if (what == "mover") {
                c.kind = CommandKind::kExpectMover;
                c.name = std::string(p.word("a mover's name"));
                const std::string_view state = p.word("'rest', 'open' or 'moving'");
                if (state != "rest" && state != "open" && state != "moving")
                    p.fail("expected 'rest', 'open' or 'moving' after the mover's name, found '" +
                           LineParser::quoted(state) + "'");
                c.count = state == "rest" ? 0 : state == "open" ? 1 : 2;
            } else {
                p.fail(
                    "expected 'primary', 'effect-lights', 'player', 'item' or 'mover' after "
                    "'expect', found '" +
                    LineParser::quoted(what) + "'");
            }
        } else if (head == "quit") {
            c.kind = CommandKind::kQuit;
        } else {
            p.fail("unknown command '" + LineParser::quoted(head) +
                   "' (expected level, tick, spawn, at, wait, key, look, flashlight, fire, "
                   "capture, expect or quit)");
        }
        p.end();
        timedSeen = true;
        if (script.commands.size() >= kMaxScriptCommands)
            p.fail("more than " + std::to_string(kMaxScriptCommands) +
                   " timed commands; expected fewer");
        script.commands.push_back(std::move(c));
    }
    return script;
}

Script loadScript(const std::string& path) {
    std::vector<uint8_t> bytes;
    try {
        bytes = world::readRegularFile(path, "a replay script", kMaxScriptBytes);
    } catch (const world::Error& e) {
        throw ScriptError(e.what());
    }
    return parseScript(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                       path);
}

}  // namespace onelight::replay
