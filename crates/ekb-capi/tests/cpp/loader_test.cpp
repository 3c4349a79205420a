// One reading: every knowledge base among the test fixtures, loaded through the C++ API
// (ekb::KnowledgeBase), the C ABI (ekb.h) and the drop-in class, agrees field by field
// with `ekb export`; a file with an error is refused with the findings `ekb check` reports.
//
// Usage: ekb-loader-test EKB_EXECUTABLE FILE...
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "environmentKnowledgeBaseInterface.h"
#include "json.hpp"

namespace {

int failures = 0;
int compared = 0;

void fail(const std::string &where, const std::string &what) {
    ++failures;
    if (failures <= 50) std::cerr << "FAIL " << where << ": " << what << "\n";
}

#define EXPECT(condition, where, what)           \
    do {                                         \
        ++compared;                              \
        if (!(condition)) fail((where), (what)); \
    } while (0)

std::string quote(const std::string &text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// The standard output of `command`, and its exit status.
std::string run(const std::string &command, int &status, const char *stderrTo = "/dev/null") {
    std::string out;
    FILE *pipe = popen((command + " 2>" + stderrTo).c_str(), "r");
    if (!pipe) throw std::runtime_error("cannot run " + command);
    char buffer[65536];
    std::size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
    int raw = pclose(pipe);
    status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return out;
}

std::string show(const std::optional<std::string_view> &text) {
    return text ? "\"" + std::string(*text) + "\"" : std::string("null");
}

void expectText(const std::string &where, const std::optional<std::string_view> &got, const json::Value &want) {
    bool same = want.isNull() ? !got : (got && *got == want.string);
    EXPECT(same, where, "got " + show(got) + ", ekb export has " + (want.isNull() ? "null" : "\"" + want.string + "\""));
}

void expectNumber(const std::string &where, double got, const json::Value &want) {
    EXPECT(got == want.number, where, "got " + std::to_string(got) + ", ekb export has " + std::to_string(want.number));
}

void expectMessages(const std::string &where, const ekb::Messages &got, const json::Value &want) {
    expectText(where + ".english", got.english, want["english"]);
    expectText(where + ".isiZulu", got.isiZulu, want["isiZulu"]);
    expectText(where + ".kinyarwanda", got.kinyarwanda, want["kinyarwanda"]);
}

void expectLocation(const std::string &where, const ekb::Location &got, const json::Value &want) {
    EXPECT(got.id == want["id"].number, where, "id " + std::to_string(got.id));
    expectText(where + ".description", got.description, want["description"]);
    const json::Value &pose = want["pose"];
    EXPECT(pose.isNull() == !got.pose, where + ".pose", "present in one only");
    if (got.pose && !pose.isNull()) {
        expectNumber(where + ".pose.x", got.pose->x, pose["x"]);
        expectNumber(where + ".pose.y", got.pose->y, pose["y"]);
        expectNumber(where + ".pose.theta", got.pose->theta, pose["theta"]);
    }
    const json::Value &target = want["gestureTarget"];
    EXPECT(target.isNull() == !got.gestureTarget, where + ".gestureTarget", "present in one only");
    if (got.gestureTarget && !target.isNull()) {
        expectNumber(where + ".gestureTarget.x", got.gestureTarget->x, target["x"]);
        expectNumber(where + ".gestureTarget.y", got.gestureTarget->y, target["y"]);
        expectNumber(where + ".gestureTarget.z", got.gestureTarget->z, target["z"]);
    }
    std::optional<std::string_view> arm;
    if (got.gestureArm) arm = *got.gestureArm == ekb::Arm::left ? "left" : "right";
    expectText(where + ".gestureArm", arm, want["gestureArm"]);
    expectMessages(where + ".preGestureMessage", got.preGestureMessage, want["preGestureMessage"]);
    expectMessages(where + ".postGestureMessage", got.postGestureMessage, want["postGestureMessage"]);
    const json::Value &words = want["culturalKnowledge"];
    EXPECT(got.culturalKnowledge.size() == words.array.size(), where + ".culturalKnowledge", "word count");
    for (std::size_t i = 0; i < got.culturalKnowledge.size() && i < words.array.size(); ++i)
        expectText(where + ".culturalKnowledge", got.culturalKnowledge[i], words.array[i]);
}

void expectTour(const std::string &where, const std::vector<std::uint32_t> &got, const json::Value &want) {
    EXPECT(got.size() == want.array.size(), where + ".tour", "length " + std::to_string(got.size()));
    for (std::size_t i = 0; i < got.size() && i < want.array.size(); ++i)
        EXPECT(got[i] == want.array[i].number, where + ".tour", "stop " + std::to_string(i));
}

// Whether `text` is printable ASCII, which escaping leaves as it is.
bool plain(const std::string &text) {
    for (unsigned char c : text)
        if (c < 0x20 || c >= 0x7f) return false;
    return true;
}

// Whether `text` holds a control character.
bool controls(const std::string &text) {
    for (unsigned char c : text)
        if (c < 0x20 || c == 0x7f) return true;
    return false;
}

// The findings of a refused file against those of `ekb check`, leaving out `ignored` rules.
void expectFindings(const std::string &where, const std::vector<ekb::Finding> &got, const json::Value &want,
                    const std::string &ignoredPrefix = "\x01") {
    std::vector<const ekb::Finding *> kept;
    for (const ekb::Finding &finding : got)
        if (finding.rule.rfind(ignoredPrefix, 0) != 0) kept.push_back(&finding);
    // The library lists them as people read them, errors first (a consequence after its
    // cause); ekb check's JSON in the file's order.
    for (std::size_t i = 1; i < kept.size(); ++i)
        EXPECT(ekb::severity_name(kept[i]->severity) != std::string("error") ||
                   ekb::severity_name(kept[i - 1]->severity) == std::string("error"),
               where + ".findings[" + std::to_string(i) + "]", "an error after a warning");
    // Both by place, then rule (findings of two rules can share a place).
    std::sort(kept.begin(), kept.end(), [](const ekb::Finding *a, const ekb::Finding *b) {
        return std::tie(a->line, a->column, a->endLine, a->endColumn, a->rule) <
               std::tie(b->line, b->column, b->endLine, b->endColumn, b->rule);
    });
    std::vector<const json::Value *> wanted;
    for (const json::Value &d : want.array) wanted.push_back(&d);
    std::sort(wanted.begin(), wanted.end(), [](const json::Value *a, const json::Value *b) {
        auto key = [](const json::Value *d) {
            return std::make_tuple((*d)["line"].number, (*d)["column"].number, (*d)["end_line"].number,
                                   (*d)["end_column"].number, (*d)["rule"].string);
        };
        return key(a) < key(b);
    });
    EXPECT(kept.size() == wanted.size(), where + ".findings",
           "count " + std::to_string(kept.size()) + ", ekb check has " + std::to_string(wanted.size()));
    for (std::size_t i = 0; i < kept.size() && i < wanted.size(); ++i) {
        const ekb::Finding &f = *kept[i];
        const json::Value &d = *wanted[i];
        std::string at = where + ".findings[" + std::to_string(i) + "]";
        EXPECT(f.rule == d["rule"].string, at, "rule " + f.rule + ", ekb check has " + d["rule"].string);
        EXPECT(ekb::severity_name(f.severity) == d["severity"].string, at, "severity");
        // A message that quotes a control or non-ASCII character of the file is escaped for
        // people (as `ekb check`'s human formats show it); the JSON keeps it raw.
        EXPECT(f.message == d["message"].string || !plain(d["message"].string), at, "message " + f.message);
        EXPECT(!controls(f.message), at, "message not escaped: " + f.message);
        EXPECT(f.file == d["file"].string, at, "file " + f.file);
        EXPECT(f.line == d["line"].number && f.column == d["column"].number, at, "position");
        EXPECT(f.endLine == d["end_line"].number && f.endColumn == d["end_column"].number, at, "end");
        EXPECT(d["location_id"].isNull() ? !f.locationId : (f.locationId && *f.locationId == d["location_id"].number),
               at, "location id");
        EXPECT(d["help"].isNull() ? !f.help : (f.help && (!plain(d["help"].string) || *f.help == d["help"].string)), at, "help");
    }
}

std::optional<std::string_view> view(ekb_str text) {
    if (!text.ptr) return std::nullopt;
    return std::string_view(text.ptr, text.len);
}

ekb::Messages messages(const ekb_messages &m) { return {view(m.english), view(m.isi_zulu), view(m.kinyarwanda)}; }

// The same file through the C ABI alone.
void throughTheCAbi(const std::string &file, const json::Value &exported) {
    std::string where = file + " (C ABI)";
    ekb_handle kb = 0;
    ekb_status status = ekb_open_path(file.data(), file.size(), nullptr, &kb);
    EXPECT(status == EKB_OK, where, "ekb_open_path");
    if (status != EKB_OK) {
        ekb_free(kb);
        return;
    }
    std::size_t count = 0;
    EXPECT(ekb_location_count(kb, &count) == EKB_OK && count == exported["locations"].array.size(), where,
           "location count");
    for (std::size_t index = 0; index < count && index < exported["locations"].array.size(); ++index) {
        ekb_location l{};
        EXPECT(ekb_location_at(kb, index, &l) == EKB_OK, where, "ekb_location_at");
        ekb::Location got{l.id, view(l.description), std::nullopt, std::nullopt, std::nullopt,
                          messages(l.pre_gesture_message), messages(l.post_gesture_message), {}};
        if (l.has_pose) got.pose = ekb::Pose{l.pose.x, l.pose.y, l.pose.theta};
        if (l.has_gesture_target) got.gestureTarget = ekb::Point{l.gesture_target.x, l.gesture_target.y, l.gesture_target.z};
        if (l.gesture_arm != EKB_ARM_NONE) got.gestureArm = l.gesture_arm == EKB_ARM_LEFT ? ekb::Arm::left : ekb::Arm::right;
        for (std::size_t w = 0; w < l.cultural_knowledge_count; ++w) {
            ekb_str word{};
            EXPECT(ekb_cultural_word(kb, l.id, w, &word) == EKB_OK, where, "ekb_cultural_word");
            got.culturalKnowledge.push_back(std::string_view(word.ptr, word.len));
        }
        expectLocation(where + " location " + std::to_string(l.id), got, exported["locations"].array[index]);
    }
    const std::uint32_t *stops = nullptr;
    std::size_t length = 0;
    EXPECT(ekb_tour(kb, &stops, &length) == EKB_OK, where, "ekb_tour");
    expectTour(where, std::vector<std::uint32_t>(stops, stops + length), exported["tour"]);
    EXPECT(ekb_free(kb) == EKB_OK, where, "ekb_free");
}

// Whether the document's fixed-size types hold every value of the export.
bool fitsTheDocumentsTypes(const json::Value &exported) {
    if (exported["tour"].array.size() > MAX_NUMBER_OF_TOUR_LOCATIONS) return false;
    for (const json::Value &l : exported["locations"].array) {
        if (l["culturalKnowledge"].array.size() > MAX_CULTURE_KEYS) return false;
        std::vector<const json::Value *> texts = {&l["description"]};
        for (const char *phase : {"preGestureMessage", "postGestureMessage"})
            for (const char *language : {"english", "isiZulu", "kinyarwanda"}) texts.push_back(&l[phase][language]);
        for (const json::Value *text : texts)
            if (text->string.size() >= STRING_LENGTH) return false;
    }
    return true;
}

void expectField(const std::string &where, const char *got, const json::Value &want) {
    expectText(where, std::string_view(got), want.isNull() ? json::Value{json::Value::Kind::string} : want);
}

// The same file through the drop-in class, named by a configuration in EKB_CONFIG.
void throughTheDropIn(const std::string &file, const std::string &configDir, const json::Value &exported,
                      const json::Value &checked, bool refused) {
    std::string where = file + " (drop-in)";
    std::string config = configDir + "/environmentKnowledgeBaseConfiguration.ini";
    std::ofstream(config) << "knowledgeBase " << file << "\nverboseMode false\n";
    setenv("EKB_CONFIG", config.c_str(), 1);
    bool fits = refused || fitsTheDocumentsTypes(exported);
    try {
        Environment::EnvironmentKnowledgeBase kb;
        EXPECT(!refused && fits, where, "loaded a file that should be refused");
        if (refused || !fits) return;
        for (const json::Value &l : exported["locations"].array) {
            KeyValueType value;
            std::string at = where + " location " + std::to_string(static_cast<long>(l["id"].number));
            EXPECT(kb.getValue(static_cast<int>(l["id"].number), &value), at, "getValue");
            EXPECT(value.key == l["id"].number, at, "key");
            expectField(at + ".description", value.robotLocationDescription, l["description"]);
            const json::Value &pose = l["pose"];
            EXPECT(value.robotLocation.x == static_cast<float>(pose["x"].number) &&
                       value.robotLocation.y == static_cast<float>(pose["y"].number) &&
                       value.robotLocation.theta == static_cast<float>(pose["theta"].number),
                   at, "robotLocation");
            const json::Value &target = l["gestureTarget"];
            EXPECT(value.gestureTarget.x == static_cast<float>(target["x"].number) &&
                       value.gestureTarget.y == static_cast<float>(target["y"].number) &&
                       value.gestureTarget.z == static_cast<float>(target["z"].number),
                   at, "gestureTarget");
            expectField(at + ".preEnglish", value.preGestureMessageEnglish, l["preGestureMessage"]["english"]);
            expectField(at + ".preIsiZulu", value.preGestureMessageIsiZulu, l["preGestureMessage"]["isiZulu"]);
            expectField(at + ".preKinyarwanda", value.preGestureMessageKinyarwanda, l["preGestureMessage"]["kinyarwanda"]);
            expectField(at + ".postEnglish", value.postGestureMessageEnglish, l["postGestureMessage"]["english"]);
            expectField(at + ".postIsiZulu", value.postGestureMessageIsiZulu, l["postGestureMessage"]["isiZulu"]);
            expectField(at + ".postKinyarwanda", value.postGestureMessageKinyarwanda,
                        l["postGestureMessage"]["kinyarwanda"]);
            const json::Value &words = l["culturalKnowledge"];
            EXPECT(value.culturalKnowledge.numberOfKeys == static_cast<int>(words.array.size()), at, "numberOfKeys");
            for (int w = 0; w < value.culturalKnowledge.numberOfKeys && w < static_cast<int>(words.array.size()); ++w)
                expectField(at + ".culturalKnowledge", value.culturalKnowledge.key[w], words.array[w]);
        }
        TourSpecificationType tour;
        bool hasTour = kb.getTour(&tour);
        EXPECT(hasTour == !exported["tour"].array.empty(), where, "getTour");
        std::vector<std::uint32_t> stops(tour.locationIdNumber, tour.locationIdNumber + tour.numberOfLocations);
        expectTour(where, stops, exported["tour"]);
        KeyValueType none;
        EXPECT(!kb.getValue(0, &none) && !kb.getValue(-1, &none), where, "getValue of no location");
    } catch (const ekb::LoadError &error) {
        EXPECT(refused || !fits, where, std::string("refused: ") + error.what());
        if (refused) expectFindings(where, error.findings(), checked["diagnostics"], "drop-in-");
        if (!refused) {
            bool named = false;
            for (const ekb::Finding &f : error.findings()) named = named || f.rule.rfind("drop-in-", 0) == 0;
            EXPECT(named, where, "refused without naming the limit");
        }
    }
}

// Several threads reading one knowledge base at once read the same.
void concurrentReaders(const ekb::KnowledgeBase &kb) {
    std::vector<std::uint32_t> tour = kb.tour();
    std::atomic<int> differences{0};
    std::vector<std::thread> readers;
    for (int t = 0; t < 4; ++t)
        readers.emplace_back([&] {
            for (int round = 0; round < 200; ++round) {
                if (kb.tour() != tour) ++differences;
                for (std::uint32_t id : tour)
                    if (!kb.location(id) || kb.location(id)->id != id) ++differences;
            }
        });
    for (std::thread &reader : readers) reader.join();
    EXPECT(differences == 0, "concurrent readers", std::to_string(differences.load()) + " differences");
}

}  // namespace

int main(int argc, char **argv) {
    if (argc < 3) {
        std::cerr << "usage: ekb-loader-test EKB_EXECUTABLE FILE...\n";
        return 2;
    }
    std::string ekb = argv[1];
    char dirTemplate[] = "/tmp/ekb-loader-test-XXXXXX";
    std::string configDir = mkdtemp(dirTemplate);
    int loaded = 0, refused = 0, otherKinds = 0;
    for (int i = 2; i < argc; ++i) {
        std::string file = argv[i];
        int checkStatus = 0, exportStatus = 0;
        json::Value checked = json::parse(run(quote(ekb) + " --isolated check --format json " + quote(file), checkStatus));
        bool hasError = false;
        for (const json::Value &d : checked["diagnostics"].array) hasError = hasError || d["severity"].string == "error";
        json::Value exported;
        std::string where = file + " (C++)";
        {
            std::string errors = configDir + "/export.err";
            std::string text = run(quote(ekb) + " --isolated export " + quote(file), exportStatus, errors.c_str());
            std::string refusal((std::istreambuf_iterator<char>(std::ifstream(errors).rdbuf())), {});
            // `ekb check` checks the culture knowledge base (...) as what it is; `ekb export`
            // and the loader refuse it as no environment knowledge base.
            bool checkedAsEnvironment = false;
            for (const json::Value &d : checked["diagnostics"].array)
                checkedAsEnvironment = checkedAsEnvironment || d["rule"].string == "not-an-environment-knowledge-base";
            bool otherKind = !checkedAsEnvironment &&
                             (exportStatus != 0 && refusal.find("not-an-environment-knowledge-base") != std::string::npos);
            if (hasError && !otherKind) {
                // Refused by both: compared below.
            } else if (otherKind || exportStatus != 0) {
                ++otherKinds;
                try {
                    ekb::KnowledgeBase::open(file);
                    fail(where, "loaded a file that is no environment knowledge base");
                } catch (const ekb::LoadError &error) {
                    EXPECT(!error.findings().empty() && error.findings()[0].rule == "not-an-environment-knowledge-base",
                           where, error.what());
                }
                continue;
            } else {
                exported = json::parse(text);
            }
        }
        try {
            ekb::KnowledgeBase kb = ekb::KnowledgeBase::open(file);
            ++loaded;
            EXPECT(!hasError && exportStatus == 0, where, "loaded a file ekb check refuses");
            if (hasError) continue;
            std::vector<ekb::Location> locations = kb.locations();
            const json::Value &want = exported["locations"];
            EXPECT(locations.size() == want.array.size(), where, "location count");
            for (std::size_t l = 0; l < locations.size() && l < want.array.size(); ++l) {
                expectLocation(where + " location " + std::to_string(locations[l].id), locations[l], want.array[l]);
                std::optional<ekb::Location> byId = kb.location(locations[l].id);
                EXPECT(byId && byId->description == locations[l].description, where, "location(id)");
            }
            expectTour(where, kb.tour(), exported["tour"]);
            expectFindings(where, kb.findings(), checked["diagnostics"]);
            if (loaded == 1) concurrentReaders(kb);
        } catch (const ekb::LoadError &error) {
            ++refused;
            EXPECT(hasError, where, std::string("refused a file ekb check passes: ") + error.what());
            expectFindings(where, error.findings(), checked["diagnostics"]);
            std::string first;
            for (const ekb::Finding &f : error.findings())
                if (f.severity == ekb::Severity::error && first.empty()) first = f.toString();
            EXPECT(std::string(error.what()).rfind(first, 0) == 0, where, std::string("what() is ") + error.what());
        }
        if (!hasError) throughTheCAbi(file, exported);
        throughTheDropIn(file, configDir, exported, checked, hasError);
    }
    // Paths the drop-in builds itself (the current folder's, here named with ESC ] 0 ; BEL)
    // and 900 KB of a file name come back escaped and short.
    {
        std::string hostile = configDir + "/\x1b]0;pwned\x07";
        std::string shown = ekb::shown(hostile + std::string(900 * 1024, 'a'));
        EXPECT(shown.find('\x1b') == std::string::npos && shown.find('\x07') == std::string::npos &&
                   shown.size() < 2000,
               "ekb::shown", shown.substr(0, 200));
        char before[4096];
        if (mkdir(hostile.c_str(), 0700) == 0 && getcwd(before, sizeof before) && chdir(hostile.c_str()) == 0) {
            const char *config = getenv("EKB_CONFIG");
            std::string kept = config ? config : "";
            unsetenv("EKB_CONFIG");
            try {
                Environment::EnvironmentKnowledgeBase kb;
                fail("the drop-in with no configuration", "loaded");
            } catch (const ekb::LoadError &error) {
                std::string what = error.what();
                EXPECT(what.find("tried ") != std::string::npos && what.find('\x1b') == std::string::npos &&
                           what.find('\x07') == std::string::npos,
                       "the drop-in's paths tried", what);
            }
            if (config) setenv("EKB_CONFIG", kept.c_str(), 1);
            if (chdir(before) != 0) fail("chdir back", before);
        } else {
            fail("a folder named with ESC and BEL", hostile);
        }
        rmdir(hostile.c_str());
    }
    // A path is a file name in bytes: one that is not UTF-8 is looked for, and a missing one
    // is a LoadError (unreadable), as any missing file, never an ekb::Error.
    try {
        ekb::KnowledgeBase::open("/nonexistent/\xff\xfe.dat");
        fail("a non-UTF-8 path", "loaded");
    } catch (const ekb::LoadError &error) {
        EXPECT(error.unreadable(), "a non-UTF-8 path", error.what());
    } catch (const std::exception &error) {
        fail("a non-UTF-8 path", std::string("not an ekb::LoadError: ") + error.what());
    }
    std::remove((configDir + "/environmentKnowledgeBaseConfiguration.ini").c_str());
    std::remove((configDir + "/export.err").c_str());
    std::remove(configDir.c_str());
    std::cout << argc - 2 << " files: " << loaded << " loaded, " << refused << " refused, " << otherKinds
              << " of another kind; " << compared
              << " comparisons, " << failures << " differences\n";
    return failures == 0 ? 0 : 1;
}
