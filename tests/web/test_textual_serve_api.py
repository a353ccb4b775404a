"""The textual-serve internals sass's server overrides or reads
(ui/serve/serve.py's SassServer, ui/serve/serve_session.py's SessionService) still are
where, and what, sass expects.  textual-serve calls them itself; a release
that renames one would leave sass's override silently unused (a shell
started again, no size clamp, no word when a session dies), so this test
fails first and says what moved."""

from __future__ import annotations

import inspect
from pathlib import Path

import pytest

pytest.importorskip("textual_serve")

from textual_serve import app_service, server

from sass_tui.ui.serve.serve import SassServer
from sass_tui.ui.serve.serve_session import SessionService

MOVED = "textual-serve moved {what}: sass_tui/ui/{module} overrides it; follow the move there"

# name -> the parameters (after self) sass's override takes and passes on
APP_SERVICE = {
    "_build_environment": ["width", "height"],
    "_open_app_process": ["width", "height"],
    "set_terminal_size": ["width", "height"],
    "start": ["width", "height"],
    "run": [],
    "stop": [],
    "send_meta": ["data"],
}
SERVER = {
    "_make_app": [],
    "_process_messages": ["websocket", "app_service"],
    "handle_index": ["request"],
    "handle_websocket": ["request"],
    "handle_download": ["request"],
    "on_startup": ["app"],
    "on_shutdown": ["app"],
    "initialize_logging": [],
    "request_exit": [],
    "serve": ["debug"],
}


@pytest.mark.parametrize(("name", "parameters"), APP_SERVICE.items())
def test_the_app_service_methods_sass_overrides_are_there(name, parameters):
    method = getattr(app_service.AppService, name, None)
    assert callable(method), MOVED.format(what=f"AppService.{name}", module="serve_session.py")
    assert list(inspect.signature(method).parameters)[1:] == parameters, MOVED.format(
        what=f"AppService.{name}'s parameters", module="serve_session.py"
    )
    assert getattr(SessionService, name) is not method or name in ("start", "send_meta")


@pytest.mark.parametrize(("name", "parameters"), SERVER.items())
def test_the_server_methods_sass_overrides_are_there(name, parameters):
    method = getattr(server.Server, name, None)
    assert callable(method), MOVED.format(what=f"Server.{name}", module="serve.py")
    assert list(inspect.signature(method).parameters)[1:] == parameters, MOVED.format(
        what=f"Server.{name}'s parameters", module="serve.py"
    )


def test_the_attributes_sass_reads_are_set_where_expected():
    """AppService keeps its process in `_process` and its stdin in `_stdin`,
    and relays output through `remote_write_bytes`; Server keeps its
    templates in `templates_path` and its downloads in `download_manager`."""
    init = inspect.getsource(app_service.AppService.__init__)
    for attribute in ("self._process", "self._stdin", "self._task", "self.remote_write_bytes"):
        assert attribute in init, MOVED.format(what=attribute, module="serve_session.py")
    made = inspect.getsource(server.Server.__init__)
    for attribute in ("self.templates_path", "self.download_manager", "self.public_url"):
        assert attribute in made, MOVED.format(what=attribute, module="serve.py")
    assert "self.templates_path" in inspect.getsource(server.Server._make_app)
    # the routes the guard names
    assert 'name="websocket"' in inspect.getsource(server.Server._make_app)
    assert 'name="download"' in inspect.getsource(server.Server._make_app)


def test_the_static_files_the_page_names_are_shipped():
    """sass's page (ui/serve/serve_page/app_index.html) loads textual-serve's
    script, stylesheet and fonts; the script still asks for Roboto Mono."""
    static = Path(server.__file__).parent / "static"
    page = (Path(inspect.getfile(SassServer)).parent / "serve_page" / "app_index.html").read_text()
    for name in (
        "js/textual.js",
        "css/xterm.css",
        "fonts/RobotoMono-VariableFont_wght.ttf",
        "fonts/RobotoMono-Italic-VariableFont_wght.ttf",
    ):
        assert (static / name).is_file(), MOVED.format(what=f"static/{name}", module="serve_page")
        assert name in page
    assert "'Roboto Mono'" in (static / "js" / "textual.js").read_text()
