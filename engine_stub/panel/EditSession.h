#pragma once
// The tweak panel's edit model, without any UI: the text of every loaded reaction file, edits
// made in place in that text (panel/YamlTextEdit.h) and applied to the running plugin at once
// through fx::Plugin::loadReactionsFromText (the same validation as a file on disk; a refused
// edit changes nothing), undo/redo, save, revert, and a check for files changed on disk.
//
// Keys are addressed as "particle.drag", "particle.lifetime[1]", "particle.colour_ramp[0].rgba[3]"
// inside reaction `reaction` (the plugin's index). An edit of a key the file leaves out adds it
// to its section (or adds the section), on a new line; every other line stays as it was.
#include <cstdint>
#include <string>
#include <vector>

#include "fx/Plugin.h"

namespace cube::panel {

/// One reaction file. Defaults: nothing loaded.
struct Document {
    std::string path;
    std::string text;         ///< what the running set was built from (edits included)
    std::string savedText;    ///< the file's content as last read or written
    bool conflict = false;    ///< the file changed on disk while it had unsaved edits
    std::string diskText;     ///< that changed content, until resolveConflict()
    bool dirty() const { return text != savedText; }
};

class EditSession {
public:
    explicit EditSession(fx::Plugin& plugin) : plugin_(plugin) {}

    /// Reads every file of the plugin's running set. False + error naming the file.
    bool open(std::string* error);
    const std::vector<Document>& documents() const { return docs_; }
    /// The document holding reaction `reaction`, or -1.
    int documentOf(int reaction) const;

    /// Sets `key` of reaction `reaction` to `value` (YAML text: "1.5", "[1, 2]", "soft") and
    /// applies it. `group`: successive edits with the same non-empty group make one undo step
    /// until endGroup() (a slider drag). False + error (the schema's message for a refused
    /// value, "file:line:col: error[Code] key: message") and nothing changed.
    bool set(int reaction, const std::string& key, const std::string& value, std::string* error,
             const std::string& group = "");
    /// True when the file spells out `key` (element keys included) for reaction `reaction`.
    bool hasEntry(int reaction, const std::string& key) const;
    /// Colour ramp stops: a copy of stop `stop` inserted after it / stop `stop` removed.
    bool duplicateStop(int reaction, int stop, std::string* error) { return editStopLine(reaction, stop, true, error); }
    bool removeStop(int reaction, int stop, std::string* error) { return editStopLine(reaction, stop, false, error); }
    /// Ends the current undo group (the drag was released).
    void endGroup() { groupOpen_ = false; }

    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    bool undo(std::string* error);
    bool redo(std::string* error);

    /// Writes document `doc`'s text to its file (a temporary file renamed over it).
    bool save(int doc, std::string* error);
    /// Reloads document `doc` from disk and applies it (an undoable edit).
    bool revert(int doc, std::string* error);
    /// Reads every file and compares it with what was last read or written: a clean document
    /// takes the new content (applied); a dirty one is marked `conflict` for the user to
    /// answer. Returns true when some document needs an answer.
    bool checkDisk(std::string* error);
    /// The user's answer: true reloads the disk content (edits dropped, undoable); false keeps
    /// the edits (the next save overwrites the file).
    bool resolveConflict(int doc, bool reloadFromDisk, std::string* error);

    /// Counts successful applies (for caches of running values).
    int version() const { return version_; }

private:
    struct Step {
        int doc = 0;
        std::string before, after;
        std::string group;
    };
    bool locate(int reaction, int* doc, std::string* error) const;
    bool editStopLine(int reaction, int stop, bool duplicate, std::string* error);
    /// Parses the text of `doc` (the file that holds `reaction`) into *text and runs
    /// edit(reactionMap, text) on it. False with *error when the file does not parse, has no
    /// such reaction, or `edit` fails (it sets *error then).
    template <class Edit>
    bool editReaction(int reaction, int doc, std::string* text, const Edit& edit, std::string* error) const;
    /// Undo (from undo_ to redo_, the text before) or redo (the other way, the text after): applies
    /// the last step of *from and moves it to *to. False when *from is empty or apply fails.
    bool replay(std::vector<Step>* from, std::vector<Step>* to, std::string Step::*text, std::string* error);
    /// Validates and applies `text` for `doc`; on success records an undo step.
    bool apply(int doc, const std::string& text, const std::string& group, bool record, std::string* error);

    fx::Plugin& plugin_;
    std::vector<Document> docs_;
    std::vector<Step> undo_, redo_;
    bool groupOpen_ = false;
    int version_ = 0;
};

}  // namespace cube::panel
