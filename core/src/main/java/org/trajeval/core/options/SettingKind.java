package org.trajeval.core.options;

/** The type of a setting's value, as written in text (a flag's argument, a YAML or JSON scalar). */
public enum SettingKind {
    /** One word of a fixed list; case-insensitive, '-' and '_' are the same. */
    CHOICE,
    /** A finite decimal number. */
    NUMBER,
    /** A whole number. */
    INTEGER,
    /** true or false; on the command line a flag without an argument. */
    SWITCH,
    /** Numbers separated by commas (a YAML list is accepted too). */
    NUMBERS,
    /** A path, resolved by the front end (relative to the manifest, inside the bundle, ...). */
    PATH,
    /** Free text whose form the setting's help names. */
    TEXT
}
