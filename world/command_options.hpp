// Command-line options as data, for onelight, onelight-bake and onelight-lab: each option is
// declared once (name, value kind and range, default, help line) in a command's table, and the
// same table writes the command's help, parses and checks its arguments, and gives back what was
// given as arguments again (the Slurm bake forwards its shard tasks' options from it). A value is
// taken whole: "12abc", "1e3" for an integer, "-5" for a count, NaN or Inf are refused. Every
// refusal throws world::Error naming the option, the value and what was expected.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace onelight::world {

enum class OptionKind {
    kFlag,     // no value
    kInteger,  // a whole number in [low, high], digits only (a sign only where low < 0)
    kReal,     // a finite number in [low, high]
    kChoice,   // one of `choices`
    kText,     // any text: a path, a name
    kSize,     // WxH, each an integer in [low, high]
    kCustom,   // text that `accepts` takes (e.g. i/N, 5%, a Slurm time limit)
};

/// Where the Slurm bake sends an option: every option of the bake's table says which.
enum class Forwarding {
    kUnmarked,  // not said: a bake table's test refuses it
    kToShards,  // every shard task is given it (it changes the shards' bytes)
    kLocal,     // the submitting command's only (where the output goes, threads, the jobs)
};

/// One option of a command.
struct CommandOption {
    std::string name;       // "--spp", "-o"
    std::string valueName;  // "N", "PATH", "WxH"; empty for a flag
    OptionKind kind = OptionKind::kFlag;
    std::string meaning;               // the help line
    std::string defaultText;           // the help's "(default: ...)"; kRequiredOption; empty: none
    double low = 0.0, high = 0.0;      // kInteger, kReal, kSize
    std::vector<std::string> choices;  // kChoice
    // What a refusal says was expected: for kInteger, kReal and kSize the words before the range
    // ("metres, a number" in [1, 10000]), else the whole of it; empty: made from the kind.
    std::string expected;
    bool (*accepts)(const std::string& text) = nullptr;  // kCustom
    Forwarding forwarding = Forwarding::kUnmarked;
};

/// The defaultText of an option the command cannot run without.
inline const std::string kRequiredOption = "required";

[[nodiscard]] CommandOption flagOption(std::string name, std::string meaning,
                                       std::string defaultText);
[[nodiscard]] CommandOption integerOption(std::string name, std::string valueName, double low,
                                          double high, std::string meaning,
                                          std::string defaultText);
[[nodiscard]] CommandOption realOption(std::string name, std::string valueName, double low,
                                       double high, std::string meaning, std::string defaultText);
[[nodiscard]] CommandOption choiceOption(std::string name, std::string valueName,
                                         std::vector<std::string> choices, std::string meaning,
                                         std::string defaultText);
[[nodiscard]] CommandOption textOption(std::string name, std::string valueName, std::string meaning,
                                       std::string defaultText);
[[nodiscard]] CommandOption sizeOption(std::string name, double low, double high,
                                       std::string meaning, std::string defaultText);
[[nodiscard]] CommandOption customOption(std::string name, std::string valueName,
                                         bool (*accepts)(const std::string&), std::string expected,
                                         std::string meaning, std::string defaultText);

/// `option` marked as forwarded to the Slurm bake's shard tasks, or as the submitter's own.
[[nodiscard]] CommandOption forwarded(CommandOption option);
[[nodiscard]] CommandOption local(CommandOption option);

/// A command: its name in messages ("onelight-bake reference"), its help's synopsis and summary,
/// its options (-h and --help are every command's), and its positional arguments.
struct CommandTable {
    std::string program;   // e.g. "onelight-bake compile": "PROGRAM --help lists the options"
    std::string synopsis;  // e.g. "onelight-bake compile LEVEL [-o LEVEL.olpak] [OPTIONS]"
    std::string summary;   // what the command does, lines after the first indented by two
    std::vector<CommandOption> options;
    std::string positionalName;  // e.g. "a level", for "no level given"; empty: none taken
    size_t minPositionals = 0, maxPositionals = 0;
};

/// What the arguments gave, checked against the table.
struct ParsedOptions {
    bool help = false;  // -h or --help was given: nothing else was read
    std::vector<std::string> positionals;
    std::vector<std::pair<std::string, std::string>> given;  // name, value ("" for a flag); the
                                                             // last of a repeated option wins

    [[nodiscard]] bool has(const std::string& name) const;
    [[nodiscard]] std::string text(const std::string& name) const;  // "" when not given
    [[nodiscard]] int64_t integer(const std::string& name) const;   // a checked kInteger's
    [[nodiscard]] double real(const std::string& name) const;       // a checked kReal's
    [[nodiscard]] std::pair<uint32_t, uint32_t> size(const std::string& name) const;  // kSize's
};

/// The help: "usage: SYNOPSIS", the summary, then every option with its default, one a line,
/// aligned, and "-h, --help".
[[nodiscard]] std::string formatHelp(const CommandTable& table);

/// Parses `arguments` (after the program and subcommand names): "--name value" (the value may
/// start with '-'), flags, positionals. -h or --help anywhere returns {help = true} at once.
/// Throws world::Error on an unknown option, a missing or bad value, a missing required option,
/// too few or too many positionals.
[[nodiscard]] ParsedOptions parseOptions(const CommandTable& table,
                                         const std::vector<std::string>& arguments);

/// The given options that `table` marks kToShards, as arguments again, in the table's order.
[[nodiscard]] std::vector<std::string> forwardedArguments(const CommandTable& table,
                                                          const ParsedOptions& parsed);

/// The whole of `text` as an integer in [low, high]; false otherwise.
[[nodiscard]] bool parseWholeInteger(const std::string& text, int64_t low, int64_t high,
                                     int64_t& out);
/// The whole of `text` as a finite number in [low, high]; false otherwise.
[[nodiscard]] bool parseFiniteNumber(const std::string& text, double low, double high, double& out);

/// `value` as the shortest text that reads it back ("%g").
[[nodiscard]] std::string shortestNumber(double value);

}  // namespace onelight::world
