// SPDX-License-Identifier: GPL-2.0-or-later
// meter_window.cpp - the GTK 3 meter window; see meter_window.hpp.
#include "meter_window.hpp"

#include <gtk/gtk.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "meter_source.hpp"

namespace hal::meter {

namespace {

struct Meter;

// The Select dialog: one tab per kind, OK / Apply / Cancel.
struct SelectDialog {
    GtkWidget* dialog = nullptr;
    GtkWidget* notebook = nullptr;
    GtkWidget* views[3] = {};           // pins, signals, parameters
};

struct Meter {
    MeterOptions opts;
    Item item;
    GtkWidget* window = nullptr;
    GtkWidget* name_label = nullptr;    // null in the small window
    GtkWidget* value_label = nullptr;
    SelectDialog select;
    std::string report_path;            // HALMETER_REPORT
    std::string last_report;
    std::string test_select;            // HALMETER_TEST_SELECT
};

constexpr Kind tab_kinds[3] = {Kind::pin, Kind::sig, Kind::param};
constexpr const char* tab_titles[3] = {"Pins", "Signals", "Parameters"};

std::string item_title(const Item& item)
{
    switch (item.kind) {
    case Kind::pin: return "Pin: " + item.name;
    case Kind::sig: return "Signal: " + item.name;
    case Kind::param: return "Parameter: " + item.name;
    default: return "-- nothing selected --";
    }
}

void report(Meter& m)
{
    if (m.report_path.empty())
        return;
    std::string line = std::string("title=") + gtk_window_get_title(GTK_WINDOW(m.window)) +
                       "|name=" + (m.name_label ? gtk_label_get_text(GTK_LABEL(m.name_label)) : "") +
                       "|value=" + gtk_label_get_text(GTK_LABEL(m.value_label));
    if (line == m.last_report)
        return;
    m.last_report = line;
    if (FILE* f = std::fopen(m.report_path.c_str(), "a")) {
        std::fprintf(f, "%s\n", line.c_str());
        std::fclose(f);
    }
}

void refresh(Meter& m)
{
    std::string text = "----";
    if (m.item.kind != Kind::none) {
        auto v = read_item(m.item);
        text = v ? *v : "(gone)";        // e.g. its component was unloaded
    }
    gtk_label_set_text(GTK_LABEL(m.value_label), text.c_str());
    report(m);
}

gboolean on_tick(gpointer data)
{
    refresh(*static_cast<Meter*>(data));
    return G_SOURCE_CONTINUE;
}

void show_item(Meter& m, const Item& item)
{
    m.item = item;
    if (m.name_label)
        gtk_label_set_text(GTK_LABEL(m.name_label), item_title(item).c_str());
    else
        gtk_window_set_title(GTK_WINDOW(m.window), item.name.c_str());
    refresh(m);
}

GtkWidget* name_list(Kind kind)
{
    GtkListStore* store = gtk_list_store_new(1, G_TYPE_STRING);
    for (const std::string& n : list_names(kind)) {
        GtkTreeIter it;
        gtk_list_store_append(store, &it);
        gtk_list_store_set(store, &it, 0, n.c_str(), -1);
    }
    GtkWidget* view = gtk_tree_view_new_with_model(GTK_TREE_MODEL(store));
    g_object_unref(store);
    gtk_tree_view_set_headers_visible(GTK_TREE_VIEW(view), FALSE);
    gtk_tree_view_append_column(GTK_TREE_VIEW(view),
                                gtk_tree_view_column_new_with_attributes("Name", gtk_cell_renderer_text_new(),
                                                                         "text", 0, nullptr));
    return view;
}

// The item selected in the dialog's current tab, if any.
Item dialog_choice(const SelectDialog& d)
{
    int page = gtk_notebook_get_current_page(GTK_NOTEBOOK(d.notebook));
    if (page < 0 || page > 2)
        return {};
    GtkTreeSelection* sel = gtk_tree_view_get_selection(GTK_TREE_VIEW(d.views[page]));
    GtkTreeModel* model;
    GtkTreeIter it;
    if (!gtk_tree_selection_get_selected(sel, &model, &it))
        return {};
    gchar* name = nullptr;
    gtk_tree_model_get(model, &it, 0, &name, -1);
    Item item{tab_kinds[page], name ? name : ""};
    g_free(name);
    return item;
}

void on_dialog_response(GtkDialog*, gint response, gpointer data)
{
    Meter& m = *static_cast<Meter*>(data);
    if (response == GTK_RESPONSE_OK || response == GTK_RESPONSE_APPLY) {
        Item chosen = dialog_choice(m.select);
        if (chosen.kind != Kind::none)
            show_item(m, chosen);
    }
    if (response != GTK_RESPONSE_APPLY) {      // OK, Cancel, window closed
        gtk_widget_destroy(m.select.dialog);
        m.select = {};
    }
}

void on_row_activated(GtkTreeView*, GtkTreePath*, GtkTreeViewColumn*, gpointer data)
{
    Meter& m = *static_cast<Meter*>(data);
    gtk_dialog_response(GTK_DIALOG(m.select.dialog), GTK_RESPONSE_OK);   // double click = OK
}

void open_select(Meter& m)
{
    if (m.select.dialog) {
        gtk_window_present(GTK_WINDOW(m.select.dialog));
        return;
    }
    SelectDialog& d = m.select;
    d.dialog = gtk_dialog_new_with_buttons("Select Item to Probe", GTK_WINDOW(m.window),
                                           GTK_DIALOG_DESTROY_WITH_PARENT, "_OK", GTK_RESPONSE_OK,
                                           "_Apply", GTK_RESPONSE_APPLY, "_Cancel", GTK_RESPONSE_CANCEL,
                                           nullptr);
    gtk_window_set_default_size(GTK_WINDOW(d.dialog), 300, 400);
    d.notebook = gtk_notebook_new();
    for (int i = 0; i < 3; i++) {
        d.views[i] = name_list(tab_kinds[i]);
        g_signal_connect(d.views[i], "row-activated", G_CALLBACK(on_row_activated), &m);
        GtkWidget* scroll = gtk_scrolled_window_new(nullptr, nullptr);
        gtk_container_add(GTK_CONTAINER(scroll), d.views[i]);
        gtk_notebook_append_page(GTK_NOTEBOOK(d.notebook), scroll, gtk_label_new(tab_titles[i]));
    }
    GtkWidget* area = gtk_dialog_get_content_area(GTK_DIALOG(d.dialog));
    gtk_box_pack_start(GTK_BOX(area), d.notebook, TRUE, TRUE, 0);
    g_signal_connect(d.dialog, "response", G_CALLBACK(on_dialog_response), &m);
    gtk_widget_show_all(d.dialog);
    if (m.item.kind != Kind::none)       // open on the tab of what is shown now
        gtk_notebook_set_current_page(GTK_NOTEBOOK(d.notebook), static_cast<int>(m.item.kind) - 1);
}

void on_select_clicked(GtkButton*, gpointer data) { open_select(*static_cast<Meter*>(data)); }

// Select 'item' in the open dialog's tab; false if it is not listed.
bool dialog_pick(SelectDialog& d, const Item& item)
{
    int page = static_cast<int>(item.kind) - 1;
    gtk_notebook_set_current_page(GTK_NOTEBOOK(d.notebook), page);
    GtkTreeModel* model = gtk_tree_view_get_model(GTK_TREE_VIEW(d.views[page]));
    GtkTreeIter it;
    for (bool more = gtk_tree_model_get_iter_first(model, &it); more; more = gtk_tree_model_iter_next(model, &it)) {
        gchar* name = nullptr;
        gtk_tree_model_get(model, &it, 0, &name, -1);
        bool match = name && item.name == name;
        g_free(name);
        if (match) {
            gtk_tree_selection_select_iter(gtk_tree_view_get_selection(GTK_TREE_VIEW(d.views[page])), &it);
            return true;
        }
    }
    return false;
}

// HALMETER_TEST_SELECT: what a user does with the dialog, once the window is up.
gboolean on_test_select(gpointer data)
{
    Meter& m = *static_cast<Meter*>(data);
    std::string spec = m.test_select;
    size_t sp = spec.find(' ');
    std::string kind = spec.substr(0, sp);
    Item item{kind == "pin" ? Kind::pin : kind == "sig" ? Kind::sig : kind == "param" ? Kind::param : Kind::none,
              sp == std::string::npos ? "" : spec.substr(sp + 1)};
    if (item.kind == Kind::none || m.opts.small) {
        std::fprintf(stderr, "halmeter: HALMETER_TEST_SELECT='%s' cannot be used here\n", spec.c_str());
        gtk_main_quit();
        return G_SOURCE_REMOVE;
    }
    open_select(m);
    if (!dialog_pick(m.select, item)) {
        std::fprintf(stderr, "halmeter: the Select dialog does not list %s\n", spec.c_str());
        gtk_dialog_response(GTK_DIALOG(m.select.dialog), GTK_RESPONSE_CANCEL);
        return G_SOURCE_REMOVE;
    }
    gtk_dialog_response(GTK_DIALOG(m.select.dialog), GTK_RESPONSE_APPLY);
    gtk_dialog_response(GTK_DIALOG(m.select.dialog), GTK_RESPONSE_OK);
    return G_SOURCE_REMOVE;
}

void build_window(Meter& m)
{
    m.window = gtk_window_new(GTK_WINDOW_TOPLEVEL);
    gtk_window_set_title(GTK_WINDOW(m.window), "Hal Meter");
    gtk_window_set_default_size(GTK_WINDOW(m.window), m.opts.width, -1);
    if (m.opts.has_geometry)
        gtk_window_move(GTK_WINDOW(m.window), m.opts.x, m.opts.y);
    g_signal_connect(m.window, "destroy", G_CALLBACK(gtk_main_quit), nullptr);

    GtkWidget* box = gtk_box_new(GTK_ORIENTATION_VERTICAL, 4);
    gtk_container_set_border_width(GTK_CONTAINER(box), 6);
    gtk_container_add(GTK_CONTAINER(m.window), box);

    m.value_label = gtk_label_new("----");
    PangoAttrList* big = pango_attr_list_new();
    pango_attr_list_insert(big, pango_attr_scale_new(2.0));
    pango_attr_list_insert(big, pango_attr_weight_new(PANGO_WEIGHT_BOLD));
    gtk_label_set_attributes(GTK_LABEL(m.value_label), big);
    pango_attr_list_unref(big);
    gtk_label_set_selectable(GTK_LABEL(m.value_label), TRUE);
    gtk_box_pack_start(GTK_BOX(box), m.value_label, TRUE, TRUE, 0);

    if (!m.opts.small) {
        m.name_label = gtk_label_new(item_title(m.item).c_str());
        gtk_box_pack_start(GTK_BOX(box), m.name_label, FALSE, FALSE, 0);
        GtkWidget* buttons = gtk_button_box_new(GTK_ORIENTATION_HORIZONTAL);
        gtk_button_box_set_layout(GTK_BUTTON_BOX(buttons), GTK_BUTTONBOX_SPREAD);
        GtkWidget* select = gtk_button_new_with_mnemonic("_Select");
        GtkWidget* exit = gtk_button_new_with_mnemonic("E_xit");
        g_signal_connect(select, "clicked", G_CALLBACK(on_select_clicked), &m);
        g_signal_connect_swapped(exit, "clicked", G_CALLBACK(gtk_widget_destroy), m.window);
        gtk_container_add(GTK_CONTAINER(buttons), select);
        gtk_container_add(GTK_CONTAINER(buttons), exit);
        gtk_box_pack_start(GTK_BOX(box), buttons, FALSE, FALSE, 0);
    } else {
        gtk_window_set_title(GTK_WINDOW(m.window), m.item.name.c_str());
    }
}

}  // namespace

int run_window(const MeterOptions& o, int& argc, char**& argv)
{
    if (!gtk_init_check(&argc, &argv)) {
        std::fprintf(stderr, "halmeter: cannot open a display (set DISPLAY, or use -t for terminal mode)\n");
        return 1;
    }
    Meter m;
    m.opts = o;
    m.item = o.item;
    if (const char* r = std::getenv("HALMETER_REPORT"))
        m.report_path = r;
    if (const char* t = std::getenv("HALMETER_TEST_SELECT"))
        m.test_select = t;
    build_window(m);
    gtk_widget_show_all(m.window);
    refresh(m);
    guint tick = g_timeout_add(static_cast<guint>(o.interval_ms), on_tick, &m);
    if (!m.test_select.empty())
        g_timeout_add(200, on_test_select, &m);
    gtk_main();
    g_source_remove(tick);
    return 0;
}

}  // namespace hal::meter
