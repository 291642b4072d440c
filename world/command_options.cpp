#include "world/command_options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "world/error.hpp"
#include "world/file_read.hpp"

namespace onelight::world {
namespace {

CommandOption option(std::string name, std::string valueName, OptionKind kind, std::string meaning,
                     std::string defaultText) {
    CommandOption o;
    o.name = std::move(name);
    o.valueName = std::move(valueName);
    o.kind = kind;
    o.meaning = std::move(meaning);
    o.defaultText = std::move(defaultText);
    return o;
}

std::string integerText(double value) {
    return std::to_string(int64_t(value));
}

// `value` as the help and the refusals write it: whole for an integer option.
std::string boundText(const CommandOption& o, double value) {
    return o.kind == OptionKind::kReal ? shortestNumber(value) : integerText(value);
}

std::string rangeText(const CommandOption& o) {
    std::string text = "[";
    text += boundText(o, o.low);
    text += ", ";
    text += boundText(o, o.high);
    text += "]";
    return text;
}

// What a refusal of `o`'s value says was expected.
std::string expectedText(const CommandOption& o) {
    switch (o.kind) {
        case OptionKind::kInteger:
            return (o.expected.empty() ? "an integer" : o.expected) + " in " + rangeText(o);
        case OptionKind::kReal:
            return (o.expected.empty() ? "a number" : o.expected) + " in " + rangeText(o);
        case OptionKind::kSize:
            return (o.expected.empty() ? "WxH" : o.expected) + ", each an integer in " +
                   rangeText(o) + ", e.g. 1280x720";
        case OptionKind::kChoice: {
            if (!o.expected.empty()) return o.expected;
            std::string text;
            for (size_t i = 0; i < o.choices.size(); ++i)
                text += (i == 0 ? "" : i + 1 == o.choices.size() ? " or " : ", ") + o.choices[i];
            return text;
        }
        case OptionKind::kText:
            return o.expected.empty() ? o.valueName : o.expected;
        case OptionKind::kCustom:
        case OptionKind::kFlag:
            return o.expected;
    }
    return o.expected;
}

bool wholeInRange(const std::string& text, double low, double high) {
    int64_t value = 0;
    return parseWholeInteger(text, int64_t(low), int64_t(high), value);
}

bool sizeAccepted(const std::string& text, double low, double high) {
    const size_t x = text.find('x');
    return x != std::string::npos && wholeInRange(text.substr(0, x), low, high) &&
           wholeInRange(text.substr(x + 1), low, high);
}

bool valueAccepted(const CommandOption& o, const std::string& text) {
    double real = 0.0;
    switch (o.kind) {
        case OptionKind::kInteger:
            return wholeInRange(text, o.low, o.high);
        case OptionKind::kReal:
            return parseFiniteNumber(text, o.low, o.high, real);
        case OptionKind::kSize:
            return sizeAccepted(text, o.low, o.high);
        case OptionKind::kChoice:
            return std::find(o.choices.begin(), o.choices.end(), text) != o.choices.end();
        case OptionKind::kText:
            return true;
        case OptionKind::kCustom:
            return o.accepts && o.accepts(text);
        case OptionKind::kFlag:
            return true;
    }
    return false;
}

std::string helpHint(const CommandTable& table) {
    return " (" + table.program + " --help lists the options)";
}

std::string flagText(const CommandOption& o) {
    return o.valueName.empty() ? o.name : o.name + " " + o.valueName;
}

// The help line of `o`: its meaning, then its range or its choices.
std::string meaningText(const CommandOption& o) {
    std::string range = boundText(o, o.low);
    range += "..";
    range += boundText(o, o.high);
    switch (o.kind) {
        case OptionKind::kInteger:
        case OptionKind::kReal:
            return o.meaning + ", " + range;
        case OptionKind::kSize:
            return o.meaning + ", " + range + " each";
        case OptionKind::kChoice:
            return o.meaning + ": " + expectedText(o);
        default:
            return o.meaning;
    }
}

const CommandOption* findOption(const CommandTable& table, const std::string& name) {
    for (const CommandOption& o : table.options)
        if (o.name == name) return &o;
    return nullptr;
}

}  // namespace

CommandOption flagOption(std::string name, std::string meaning, std::string defaultText) {
    return option(std::move(name), "", OptionKind::kFlag, std::move(meaning),
                  std::move(defaultText));
}

namespace {

CommandOption rangedOption(std::string name, std::string valueName, OptionKind kind, double low,
                           double high, std::string meaning, std::string defaultText) {
    CommandOption o = option(std::move(name), std::move(valueName), kind, std::move(meaning),
                             std::move(defaultText));
    o.low = low;
    o.high = high;
    return o;
}

}  // namespace

CommandOption integerOption(std::string name, std::string valueName, double low, double high,
                            std::string meaning, std::string defaultText) {
    return rangedOption(std::move(name), std::move(valueName), OptionKind::kInteger, low, high,
                        std::move(meaning), std::move(defaultText));
}

CommandOption realOption(std::string name, std::string valueName, double low, double high,
                         std::string meaning, std::string defaultText) {
    return rangedOption(std::move(name), std::move(valueName), OptionKind::kReal, low, high,
                        std::move(meaning), std::move(defaultText));
}

CommandOption choiceOption(std::string name, std::string valueName,
                           std::vector<std::string> choices, std::string meaning,
                           std::string defaultText) {
    CommandOption o = option(std::move(name), std::move(valueName), OptionKind::kChoice,
                             std::move(meaning), std::move(defaultText));
    o.choices = std::move(choices);
    return o;
}

CommandOption textOption(std::string name, std::string valueName, std::string meaning,
                         std::string defaultText) {
    return option(std::move(name), std::move(valueName), OptionKind::kText, std::move(meaning),
                  std::move(defaultText));
}

CommandOption sizeOption(std::string name, double low, double high, std::string meaning,
                         std::string defaultText) {
    CommandOption o = option(std::move(name), "WxH", OptionKind::kSize, std::move(meaning),
                             std::move(defaultText));
    o.low = low;
    o.high = high;
    return o;
}

CommandOption customOption(std::string name, std::string valueName,
                           bool (*accepts)(const std::string&), std::string expected,
                           std::string meaning, std::string defaultText) {
    CommandOption o = option(std::move(name), std::move(valueName), OptionKind::kCustom,
                             std::move(meaning), std::move(defaultText));
    o.accepts = accepts;
    o.expected = std::move(expected);
    return o;
}

CommandOption forwarded(CommandOption option) {
    option.forwarding = Forwarding::kToShards;
    return option;
}

CommandOption local(CommandOption option) {
    option.forwarding = Forwarding::kLocal;
    return option;
}

bool ParsedOptions::has(const std::string& name) const {
    for (const auto& [n, v] : given)
        if (n == name) return true;
    return false;
}

std::string ParsedOptions::text(const std::string& name) const {
    std::string value;
    for (const auto& [n, v] : given)
        if (n == name) value = v;  // the last wins
    return value;
}

int64_t ParsedOptions::integer(const std::string& name) const {
    int64_t value = 0;
    if (!parseWholeInteger(text(name), INT64_MIN, INT64_MAX, value))
        throw Error(name + ": not an integer option or not given");
    return value;
}

double ParsedOptions::real(const std::string& name) const {
    double value = 0.0;
    if (!parseFiniteNumber(text(name), -HUGE_VAL, HUGE_VAL, value))
        throw Error(name + ": not a number option or not given");
    return value;
}

std::pair<uint32_t, uint32_t> ParsedOptions::size(const std::string& name) const {
    const std::string value = text(name);
    const size_t x = value.find('x');
    int64_t width = 0, height = 0;
    if (x == std::string::npos || !parseWholeInteger(value.substr(0, x), 0, UINT32_MAX, width) ||
        !parseWholeInteger(value.substr(x + 1), 0, UINT32_MAX, height))
        throw Error(name + ": not a size option or not given");
    return {uint32_t(width), uint32_t(height)};
}

std::string formatHelp(const CommandTable& table) {
    size_t width = std::string("-h, --help").size();
    for (const CommandOption& o : table.options) width = std::max(width, flagText(o).size());
    std::string text = "usage: " + table.synopsis + "\n  " + table.summary + "\n";
    auto line = [&](const std::string& flag, const std::string& meaning,
                    const std::string& defaultText) {
        text += "  " + flag + std::string(width + 2 - flag.size(), ' ') + meaning +
                (defaultText.empty()              ? ""
                 : defaultText == kRequiredOption ? " (required)"
                                                  : " (default: " + defaultText + ")") +
                "\n";
    };
    for (const CommandOption& o : table.options) line(flagText(o), meaningText(o), o.defaultText);
    line("-h, --help", "this help", "");
    return text;
}

ParsedOptions parseOptions(const CommandTable& table, const std::vector<std::string>& arguments) {
    ParsedOptions parsed;
    for (const std::string& a : arguments)
        if (a == "-h" || a == "--help") {
            parsed.help = true;
            return parsed;
        }
    for (size_t i = 0; i < arguments.size(); ++i) {
        const std::string& a = arguments[i];
        const CommandOption* o = findOption(table, a);
        if (!o) {
            if (a.empty() || a[0] == '-' || parsed.positionals.size() >= table.maxPositionals)
                throw Error("unexpected argument '" + clipForMessage(a) + "'" + helpHint(table));
            parsed.positionals.push_back(a);
            continue;
        }
        if (o->kind == OptionKind::kFlag) {
            parsed.given.emplace_back(o->name, "");
            continue;
        }
        if (i + 1 >= arguments.size())
            throw Error(o->name + " needs a value: expected " + expectedText(*o));
        const std::string& value = arguments[++i];
        if (!valueAccepted(*o, value))
            throw Error(o->name + " '" + clipForMessage(value) + "': expected " + expectedText(*o));
        parsed.given.emplace_back(o->name, value);
    }
    for (const CommandOption& o : table.options)
        if (o.defaultText == kRequiredOption && !parsed.has(o.name))
            throw Error(flagText(o) + " is required" + helpHint(table));
    if (parsed.positionals.size() < table.minPositionals)
        throw Error("no " + table.positionalName + " given" + helpHint(table));
    return parsed;
}

std::vector<std::string> forwardedArguments(const CommandTable& table,
                                            const ParsedOptions& parsed) {
    std::vector<std::string> arguments;
    for (const CommandOption& o : table.options) {
        if (o.forwarding != Forwarding::kToShards || !parsed.has(o.name)) continue;
        arguments.push_back(o.name);
        if (o.kind != OptionKind::kFlag) arguments.push_back(parsed.text(o.name));
    }
    return arguments;
}

bool parseWholeInteger(const std::string& text, int64_t low, int64_t high, int64_t& out) {
    int64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || stop != end || value < low || value > high)
        return false;
    out = value;
    return true;
}

bool parseFiniteNumber(const std::string& text, double low, double high, double& out) {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || stop != end || !std::isfinite(value) ||
        value < low || value > high)
        return false;
    out = value;
    return true;
}

std::string shortestNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
}

}  // namespace onelight::world
