// SPDX-License-Identifier: GPL-2.0-or-later
// snapshot.cpp - see snapshot.hpp.
#include "snapshot.hpp"

#include <algorithm>
#include <cstring>

namespace hal::halcmd {

namespace {

// hal_query_* callbacks: copy the record and continue.
template <typename Info>
int push_info(const Info* info, void* ctx)
{
    static_cast<std::vector<Info>*>(ctx)->push_back(*info);
    return 0;
}

int push_name(const char* name, void* ctx)
{
    static_cast<std::vector<std::string>*>(ctx)->emplace_back(name);
    return 0;
}

template <typename Info>
void sort_by_name(std::vector<Info>& v)
{
    std::sort(v.begin(), v.end(), [](const Info& a, const Info& b) { return std::strcmp(a.name, b.name) < 0; });
}

}  // namespace

Snapshot take_snapshot()
{
    Snapshot s;
    hal_query_comps(push_info<hal_comp_info>, &s.comps);
    hal_query_pins(push_info<hal_pin_info>, &s.pins);
    hal_query_params(push_info<hal_param_info>, &s.params);
    hal_query_sigs(push_info<hal_sig_info>, &s.sigs);
    hal_query_functs(push_info<hal_funct_info>, &s.functs);
    hal_query_aliases(push_info<hal_alias_info>, &s.aliases);
    std::sort(s.aliases.begin(), s.aliases.end(), [](const hal_alias_info& a, const hal_alias_info& b) {
        return std::strcmp(a.alias, b.alias) < 0;
    });
    std::vector<hal_thread_info> threads;
    hal_query_threads(push_info<hal_thread_info>, &threads);

    std::sort(s.comps.begin(), s.comps.end(),
              [](const hal_comp_info& a, const hal_comp_info& b) { return a.id < b.id; });
    sort_by_name(s.pins);
    sort_by_name(s.params);
    sort_by_name(s.sigs);
    sort_by_name(s.functs);
    sort_by_name(threads);
    for (const hal_thread_info& t : threads) {
        ThreadEntry e{t, {}};
        hal_query_thread_functs(t.name, push_name, &e.functs);
        s.threads.push_back(std::move(e));
    }
    return s;
}

}  // namespace hal::halcmd
