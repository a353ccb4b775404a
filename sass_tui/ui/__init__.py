"""The Textual user interface: the app and what every screen shares at the top;
the rooms are spreadsheet/, query/, serve/ and widgets/."""
