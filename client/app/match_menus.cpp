#include "match_menus.hpp"

#include "carrom/client/how_to_play.hpp"
#include "draw_util.hpp"
#include "palette.hpp"

#include <array>
#include <cmath>
#include <utility>

namespace carrom::client::app {
namespace {

constexpr std::array<proto::RuleSet, 4> kMenuRuleSets{
    proto::RuleSet::Icf, proto::RuleSet::Seed, proto::RuleSet::Freestyle, proto::RuleSet::DiscPool};
constexpr int kTipSteps = 4;
constexpr int kVolumeStep = 10; // percent

std::vector<std::string> menu_bar_labels(bool muted) {
    return {"Rules", "Settings", muted ? "Sound: off" : "Sound: on", "Leave"};
}

bool key_pressed(const sf::Event& e, sf::Keyboard::Key k) {
    return e.type == sf::Event::KeyPressed && e.key.code == k;
}

} // namespace

MatchMenus::MatchMenus(std::string path, SettingsLoad loaded)
    : path_(std::move(path)), settings_(loaded.settings), problem_(std::move(loaded.problem)) {}

void MatchMenus::change(const Settings& next) {
    settings_ = next;
    if (!path_.empty()) {
        problem_ = save_settings(path_, settings_);
    }
}

void MatchMenus::ask_leave(std::string consequence) {
    leave_consequence_ = std::move(consequence);
    open_ = Open::Leave;
}

void MatchMenus::open_rules(proto::RuleSet rule_set) {
    rules_tab_ = static_cast<int>(rule_set);
    open_ = Open::Rules;
}

std::string MatchMenus::open_name() const {
    switch (open_) {
    case Open::Leave:
        return "leave";
    case Open::Rules:
        return "rules";
    case Open::Settings:
        return "settings";
    case Open::None:
        break;
    }
    return "";
}

MatchMenus::Outcome MatchMenus::dialog_event(const sf::Event& e) {
    Outcome out;
    out.used = e.type == sf::Event::KeyPressed || e.type == sf::Event::MouseButtonPressed ||
               e.type == sf::Event::MouseButtonReleased || e.type == sf::Event::MouseMoved ||
               e.type == sf::Event::TextEntered;
    const std::optional<int> button = dialog_.clicked(e);
    switch (open_) {
    case Open::Leave:
        if (key_pressed(e, sf::Keyboard::Escape) || key_pressed(e, sf::Keyboard::N) ||
            button == 0) {
            open_ = Open::None;
        } else if (key_pressed(e, sf::Keyboard::Enter) || key_pressed(e, sf::Keyboard::Y) ||
                   button == 1) {
            open_ = Open::None;
            out.leave = true;
        }
        break;
    case Open::Rules:
        if (button && *button < 4) {
            rules_tab_ = *button;
        } else if (button == 4) {
            Settings next = settings_;
            next.coached = false;
            change(next);
            tip_step_ = 0;
            open_ = Open::None;
        } else if (button == 5 || key_pressed(e, sf::Keyboard::Escape) ||
                   key_pressed(e, sf::Keyboard::H) || key_pressed(e, sf::Keyboard::F1)) {
            open_ = Open::None;
        }
        break;
    case Open::Settings: {
        Settings next = settings_;
        if (button == 0) {
            next.volume = std::max(next.volume - kVolumeStep, 0);
        } else if (button == 1) {
            next.volume = std::min(next.volume + kVolumeStep, 100);
        } else if (button == 2 || key_pressed(e, sf::Keyboard::M)) {
            next.muted = !next.muted;
        } else if (button == 3) {
            next.reduced_motion = !next.reduced_motion;
        } else if (button == 4 || key_pressed(e, sf::Keyboard::Escape)) {
            open_ = Open::None;
        }
        if (!(next == settings_)) {
            change(next);
        }
        break;
    }
    case Open::None:
        break;
    }
    return out;
}

MatchMenus::Outcome MatchMenus::on_event(const sf::Event& e, bool in_room,
                                         proto::RuleSet rule_set) {
    if (open_ != Open::None) {
        return dialog_event(e);
    }
    Outcome out;
    if (tips_shown_) {
        if (const std::optional<int> b = tips_.clicked(e)) {
            out.used = true;
            if (*b == 0 && tip_step_ + 1 < kTipSteps) {
                ++tip_step_;
            } else {
                Settings next = settings_;
                next.coached = true;
                change(next);
            }
            return out;
        }
    }
    if (!in_room) {
        if (key_pressed(e, sf::Keyboard::F1)) {
            open_ = Open::Rules; // at the tab last shown (the lobby's choice when its button)
            out.used = true;
        }
        return out;
    }
    std::optional<int> bar;
    if (e.type == sf::Event::MouseButtonPressed && e.mouseButton.button == sf::Mouse::Left) {
        const Vec2 p{static_cast<double>(e.mouseButton.x), static_cast<double>(e.mouseButton.y)};
        for (std::size_t i = 0; i < bar_.size(); ++i) {
            if (bar_[i].contains(p)) {
                bar = static_cast<int>(i);
            }
        }
    }
    if (bar == 0 || key_pressed(e, sf::Keyboard::H) || key_pressed(e, sf::Keyboard::F1)) {
        open_rules(rule_set);
        out.used = true;
    } else if (bar == 1) {
        open_ = Open::Settings;
        out.used = true;
    } else if (bar == 2 || key_pressed(e, sf::Keyboard::M)) {
        Settings next = settings_;
        next.muted = !next.muted;
        change(next);
        out.used = true;
    } else if (bar == 3 || key_pressed(e, sf::Keyboard::L)) {
        out.want_leave = true;
        out.used = true;
    }
    return out;
}

double MatchMenus::layout_bar(TextCache& texts, const Rect& bar) {
    const double h = std::round(bar.h * 0.8);
    const auto size = static_cast<unsigned>(std::lround(h * 0.5));
    const double gap = 6.0;
    bar_.clear();
    double x = bar.x + bar.w - gap;
    std::vector<std::string> labels = menu_bar_labels(settings_.muted);
    std::vector<Rect> rects(labels.size());
    for (std::size_t i = labels.size(); i-- > 0;) {
        const double w = std::round(static_cast<double>(texts.width(labels[i], size)) + h * 0.8);
        x -= w;
        rects[i] = Rect{std::round(x), std::round(bar.y + (bar.h - h) / 2.0), w, h};
        x -= gap;
    }
    bar_ = rects;
    return bar.x + bar.w - x;
}

void MatchMenus::sketch_bar(Sketch& sketch) const {
    const std::vector<std::string> labels = menu_bar_labels(settings_.muted);
    for (std::size_t i = 0; i < bar_.size(); ++i) {
        const Rect& r = bar_[i];
        sketch.panel(r, kButton, kGold, 1.0f);
        sketch.text(labels[i], static_cast<unsigned>(std::lround(r.h * 0.5)), f(r.x + r.w / 2.0),
                    f(r.y + r.h / 2.0), kText, Align::Centre);
    }
}

void MatchMenus::draw_dialog(sf::RenderTarget& target, Blitter& blitter, TextCache& texts,
                             const Rect& board, const Rect& band) {
    Dialog d;
    const Rect* area = &band;
    switch (open_) {
    case Open::None:
        dialog_.hide();
        return;
    case Open::Leave:
        d.title = "Leave and forfeit?";
        d.lines = {leave_consequence_};
        d.buttons = {"Stay (Esc)", "Leave (Enter)"};
        area = &board;
        break;
    case Open::Rules: {
        const proto::RuleSet rule_set = kMenuRuleSets[static_cast<std::size_t>(rules_tab_)];
        const HowToPlay h = how_to_play(rule_set);
        d.title = "How to play: " + h.title;
        d.lines = h.rules;
        d.lines.emplace_back("");
        for (const std::string& c : controls_help()) {
            d.lines.push_back(c);
        }
        d.lines.emplace_back("Keys: H rules, M sound on or off, L leave, Escape closes this.");
        for (const proto::RuleSet r : kMenuRuleSets) {
            d.buttons.push_back(how_to_play(r).title);
        }
        d.buttons.emplace_back("First-game tips again");
        d.buttons.emplace_back("Close");
        d.chosen = rules_tab_;
        break;
    }
    case Open::Settings:
        d.title = "Settings";
        d.lines = {"Sound volume: " + std::to_string(settings_.volume) + "%",
                   std::string("Sound: ") + (settings_.muted ? "off" : "on"),
                   std::string("Reduced motion (pocketed pieces vanish at once): ") +
                       (settings_.reduced_motion ? "on" : "off"),
                   path_.empty() ? "Not kept: no settings file."
                                 : (problem_.empty() ? "Kept in " + path_ : problem_)};
        d.buttons = {"Volume -", "Volume +", settings_.muted ? "Sound on" : "Mute",
                     "Reduced motion", "Close"};
        break;
    }
    dialog_.draw(target, blitter, texts, *area, d, false);
}

double MatchMenus::draw_tips(sf::RenderTarget& target, Blitter& blitter, TextCache& texts,
                             const Rect& side, bool playing, proto::RuleSet rule_set) {
    tips_shown_ = playing && !settings_.coached && side.w > 0.0 && side.h > 0.0;
    if (!tips_shown_) {
        tips_.hide();
        return 0.0;
    }
    Dialog d;
    d.lines = {walkthrough_steps(rule_set)[static_cast<std::size_t>(tip_step_)]};
    d.buttons = {tip_step_ + 1 < kTipSteps ? "Next" : "Got it", "Skip"};
    return tips_.draw(target, blitter, texts, side, d, true);
}

} // namespace carrom::client::app
