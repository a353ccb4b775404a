"""Files: PEABODY .fig files (writer and reader), population statistics files,
worksheets, glTF and X3D writers, a target's sample file, a family's files,
atomic writes and file names as users type them.

May import: every other room of the model; nothing imports files' writers but
the layers above (db, ui, cli) and the readers that fill the model."""
