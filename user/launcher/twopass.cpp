// SPDX-License-Identifier: GPL-2.0-or-later
// twopass.cpp - see twopass.hpp.
#include "twopass.hpp"

#include <map>

#include "plan.hpp"

namespace hal::launcher {

namespace {

struct Loadrt {
    size_t index;                      // into pass0
    std::string module;
    std::vector<std::string> other;    // arguments other than count=/names=
    long count = 0;
    std::string names;
};

std::string join(const std::vector<std::string>& words)
{
    std::string out;
    for (const std::string& w : words)
        out += (out.empty() ? "" : " ") + w;
    return out;
}

std::string render(const Loadrt& l)
{
    std::vector<std::string> w{"loadrt", l.module};
    w.insert(w.end(), l.other.begin(), l.other.end());
    if (l.count > 0)
        w.push_back("count=" + std::to_string(l.count));
    if (!l.names.empty())
        w.push_back("names=" + l.names);
    return join(w);
}

}  // namespace

Result<TwoPass> twopass_split(const std::vector<std::pair<std::string, std::string>>& files)
{
    TwoPass out;
    std::map<std::string, Loadrt> loaded;   // module -> its merged line
    for (const auto& [path, text] : files) {
        std::vector<std::string> lines;
        size_t start = 0;
        while (start < text.size()) {
            size_t nl = text.find('\n', start);
            if (nl == std::string::npos)
                nl = text.size();
            lines.push_back(text.substr(start, nl - start));
            start = nl + 1;
        }
        for (size_t i = 0; i < lines.size(); i++) {
            // a logical line: backslash-continued physical lines
            size_t first = i;
            std::string logical = lines[i];
            while (!logical.empty() && logical.back() == '\\' && i + 1 < lines.size()) {
                logical.pop_back();
                logical += " " + lines[++i];
            }
            std::string code = logical.substr(0, logical.find('#'));
            std::vector<std::string> words = split_words(code);
            if (words.empty() || (words[0] != "loadrt" && words[0] != "loadusr"))
                continue;
            for (size_t k = first; k <= i; k++)
                lines[k].clear();      // pass 1 skips it, line numbers stay
            std::string where = path + ":" + std::to_string(first + 1);
            if (words[0] == "loadusr" || words.size() < 2) {
                out.pass0.push_back({join(words), where});
                continue;
            }
            Loadrt l{out.pass0.size(), words[1], {}, 0, {}};
            bool counted = false;
            for (size_t k = 2; k < words.size(); k++) {
                const std::string& a = words[k];
                if (a.starts_with("count=")) {
                    try {
                        l.count = std::stol(a.substr(6));
                        counted = true;
                    } catch (...) {
                        return Error{-22, where + ": bad " + a};
                    }
                } else if (a.starts_with("names=")) {
                    l.names = a.substr(6);
                } else {
                    l.other.push_back(a);
                }
            }
            auto it = loaded.find(l.module);
            if (it != loaded.end() && it->second.other == l.other && (counted || !l.names.empty())) {
                Loadrt& m = it->second;   // merge into the first line
                m.count += l.count;
                if (!l.names.empty())
                    m.names += (m.names.empty() ? "" : ",") + l.names;
                out.pass0[m.index].line = render(m);
                continue;
            }
            out.pass0.push_back({join(words), where});
            if (it == loaded.end())
                loaded.emplace(l.module, l);
        }
        std::string rest;
        for (const std::string& l : lines)
            rest += l + "\n";
        out.pass1.push_back({path, rest});
    }
    return out;
}

}  // namespace hal::launcher
