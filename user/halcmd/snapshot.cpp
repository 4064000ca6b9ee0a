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

// The same, for the records whose name the filter keeps.
template <typename Info>
struct Filtered {
    std::vector<Info>* out;
    const std::function<bool(std::string_view)>* keep;
};

template <typename Info>
int push_kept(const Info* info, void* ctx)
{
    auto* f = static_cast<Filtered<Info>*>(ctx);
    if ((*f->keep)(info->name))
        f->out->push_back(*info);
    return 0;
}

template <typename Info>
void query(int (*q)(int (*)(const Info*, void*), void*), std::vector<Info>& out, bool filter,
           const std::function<bool(std::string_view)>& keep)
{
    if (filter && keep) {
        Filtered<Info> f{&out, &keep};
        q(push_kept<Info>, &f);
    } else {
        q(push_info<Info>, &out);
    }
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

Snapshot take_snapshot(unsigned kinds, unsigned filtered,
                       const std::function<bool(std::string_view)>& keep)
{
    Snapshot s;
    if (kinds & snap_comps) {
        query(hal_query_comps, s.comps, filtered & snap_comps, keep);
        std::sort(s.comps.begin(), s.comps.end(),
                  [](const hal_comp_info& a, const hal_comp_info& b) { return a.id < b.id; });
    }
    if (kinds & snap_pins) {
        query(hal_query_pins, s.pins, filtered & snap_pins, keep);
        sort_by_name(s.pins);
    }
    if (kinds & snap_params) {
        query(hal_query_params, s.params, filtered & snap_params, keep);
        sort_by_name(s.params);
    }
    if (kinds & snap_sigs) {
        query(hal_query_sigs, s.sigs, filtered & snap_sigs, keep);
        sort_by_name(s.sigs);
    }
    if (kinds & snap_functs) {
        query(hal_query_functs, s.functs, filtered & snap_functs, keep);
        sort_by_name(s.functs);
    }
    if (kinds & snap_aliases) {
        hal_query_aliases(push_info<hal_alias_info>, &s.aliases);  // few; never filtered
        std::sort(s.aliases.begin(), s.aliases.end(),
                  [](const hal_alias_info& a, const hal_alias_info& b) { return std::strcmp(a.alias, b.alias) < 0; });
    }
    if (kinds & snap_threads) {
        std::vector<hal_thread_info> threads;
        query(hal_query_threads, threads, filtered & snap_threads, keep);
        sort_by_name(threads);
        for (const hal_thread_info& t : threads) {
            ThreadEntry e{t, {}};
            hal_query_thread_functs(t.name, push_name, &e.functs);
            s.threads.push_back(std::move(e));
        }
    }
    return s;
}

}  // namespace hal::halcmd
