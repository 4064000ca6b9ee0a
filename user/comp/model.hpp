// SPDX-License-Identifier: GPL-2.0-or-later
// model.hpp - a parsed .comp file (comp(1), LANGUAGE.md): what the parser builds and
// the C and man-page generators read. Plain data, no behaviour beyond lookups.
#pragma once

#include <string>
#include <vector>

namespace hal::comp {

enum class HalType { Bit, Float, S32, U32, S64, U64 };
enum class Dir { In, Out, Io, Ro, Rw };  // In/Out/Io for pins, Ro/Rw for params

// One pin or param declaration: "pin out bit out-#[8 : personality] = 0 if X "doc";"
struct Item {
    bool is_pin = true;
    std::string name;           // as written, e.g. "out-#", "in_"
    HalType type = HalType::Bit;
    Dir dir = Dir::In;
    int array_size = 0;         // 0: not an array
    std::string array_count;    // C expression giving this instance's size; empty: array_size
    std::string default_value;  // as written; empty: none
    std::string condition;      // C expression after "if"; empty: always
    std::string doc;
    int line = 0;
};

struct Function {
    std::string name;  // "_" is the instance prefix itself
    bool fp = true;
    std::string doc;
    int line = 0;
};

struct Variable {
    std::string ctype;          // "double", "int", "hal_s32_t", ...
    std::string stars;          // "" or "*", "**" for pointers
    std::string name;
    int array_size = 0;
    std::string default_value;
    int line = 0;
};

struct ModParam {
    std::string type;  // int, long, string, dummy
    std::string name;
    std::string default_value;  // C text ("5", "\"abc\"")
    std::string doc;
    int line = 0;
};

struct Option {
    std::string name;
    std::string value;  // "yes" when only the name was given
    int line = 0;
};

struct Component {
    std::string file;  // path as given, for messages and #line
    std::string name;
    int line = 0;  // of the component declaration
    std::string doc;
    std::vector<Item> items;  // pins and params in declaration order
    std::vector<Function> functions;
    std::vector<Variable> variables;
    std::vector<ModParam> modparams;
    std::vector<Option> options;
    std::vector<std::string> includes;  // "<x.h>" or "\"x.h\""
    std::string license, author, description, notes, see_also;
    std::string code;   // the C after ";;"
    int code_line = 0;  // line of the first line of code
    int max_personalities = 64;  // size of personality=, comp --personalities=N

    const Option* find_option(const std::string& name) const;
    bool option_on(const std::string& name) const;        // present and not no/false/0
    std::string option_value(const std::string& name) const;  // "" if absent
    bool is_userspace() const { return option_on("userspace"); }
    bool is_singleton() const { return option_on("singleton"); }
    bool has_personality() const { return option_on("personality"); }
};

const char* type_name(HalType t);  // "bit", "float", "s32", "u32"
const char* dir_name(Dir d);       // "in", "out", "io", "r", "rw"

}  // namespace hal::comp
