// SPDX-License-Identifier: GPL-2.0-or-later
// sampler_options.cpp - parse halsampler's options (getopt-style: "-c 1", "-c1",
// "-tn 5", "--" ends options).
#include "sampler_options.hpp"

#include <string_view>

#include "fifo_attach.hpp"

namespace hal {

Result<SamplerOptions> parse_sampler_options(std::span<char* const> args)
{
    SamplerOptions opt;
    bool have_file = false;
    bool options_done = false;

    for (size_t i = 1; i < args.size(); i++) {
        std::string_view a = args[i];
        if (options_done || a.size() < 2 || a[0] != '-') {
            if (have_file)
                return Error{-EINVAL, "more than one FILENAME given ('" + opt.filename + "', '" +
                                          std::string(a) + "')"};
            opt.filename = std::string(a);
            have_file = true;
            continue;
        }
        if (a == "--") {
            options_done = true;
            continue;
        }
        for (size_t j = 1; j < a.size(); j++) {
            char c = a[j];
            if (c == 't') {
                opt.tag = true;
            } else if (c == 'h') {
                opt.help = true;
            } else if (c == 'c' || c == 'n') {
                std::string_view value = a.substr(j + 1);
                if (value.empty()) {
                    if (i + 1 >= args.size())
                        return Error{-EINVAL, std::string("option -") + c + " needs a value"};
                    value = args[++i];
                }
                if (c == 'c') {
                    auto v = parse_number(value, 0, HAL_FIFO_MAX_FIFOS - 1);
                    if (!v)
                        return Error{-EINVAL, "-c " + std::string(value) +
                                                  ": CHAN must be a FIFO number 0.." +
                                                  std::to_string(HAL_FIFO_MAX_FIFOS - 1)};
                    opt.channel = static_cast<int>(*v);
                } else {
                    auto v = parse_number(value, 0, 1LL << 62);
                    if (!v)
                        return Error{-EINVAL, "-n " + std::string(value) +
                                                  ": COUNT must be a number of samples >= 0"};
                    opt.count = static_cast<unsigned long long>(*v);
                }
                break;  // the rest of this argument was the value
            } else {
                return Error{-EINVAL, std::string("unknown option -") + c};
            }
        }
    }
    return opt;
}

}  // namespace hal
