"""A throwaway PostgreSQL cluster for tests and benchmarks: initdb and pg_ctl of
Debian's server (`apt-get install postgresql`, .ci/run) on a free port, in a
temporary directory, stopped and removed at the end.

initdb and pg_ctl refuse to run as root: as root they run as the `postgres`
user (or `nobody`) through runuser, in a directory that user owns.
"""

from __future__ import annotations

import contextlib
import os
import pwd
import shutil
import socket
import subprocess
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path


def server_bin() -> Path | None:
    """The newest installed server's bin directory (initdb and pg_ctl), or None."""
    found = sorted(
        Path("/usr/lib/postgresql").glob("*/bin"),
        key=lambda p: int(p.parent.name) if p.parent.name.isdigit() else 0,
    )
    for folder in reversed(found):
        if (folder / "initdb").is_file() and (folder / "pg_ctl").is_file():
            return folder
    on_path = shutil.which("pg_ctl")
    return Path(on_path).parent if on_path and shutil.which("initdb") else None


def why_not() -> str | None:
    """Why no cluster can be started here, or None."""
    try:
        import psycopg  # noqa: F401
    except ImportError:
        return "psycopg is not installed (pip install -e '.[postgres]')"
    if server_bin() is None:
        return "no PostgreSQL server binaries (apt-get install postgresql)"
    if os.geteuid() == 0 and not shutil.which("runuser"):
        return "running as root without runuser: initdb refuses root"
    return None


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class Cluster:
    def __init__(self) -> None:
        self.bin = server_bin()
        assert self.bin is not None, why_not()
        self.folder = Path(tempfile.mkdtemp(prefix="sass-pg-"))
        self.data = self.folder / "data"
        self.port = _free_port()
        self.user: str | None = None
        if os.geteuid() == 0:
            self.user = "postgres" if _has_user("postgres") else "nobody"
            entry = pwd.getpwnam(self.user)
            os.chown(self.folder, entry.pw_uid, entry.pw_gid)

    def _run(self, *argv: str) -> subprocess.CompletedProcess[str]:
        command = [str(self.bin / argv[0]), *argv[1:]]
        if self.user:
            command = ["runuser", "-u", self.user, "--", *command]
        return subprocess.run(
            command, capture_output=True, text=True, timeout=120, cwd=self.folder, check=True
        )

    def init(self) -> None:
        self._run(
            "initdb", "-D", str(self.data), "-A", "trust", "-U", "sass", "-E", "UTF8",
            "--locale=C", "--no-sync",
        )  # fmt: skip

    def start(self) -> None:
        # A throwaway server is never recovered, so nothing it writes for a
        # crash is needed: no fsync, no WAL beyond what a clean stop needs
        # (wal_level=minimal lets a COPY into a table made in its own
        # transaction skip the WAL), no checkpoint in the middle of an import
        # (CREATE DATABASE ... FILE_COPY still makes one), and no autovacuum
        # (its analyses of the imports, ~3 CPU-seconds a run).  Together:
        # tests/db 268 -> 250 CPU-seconds of the machine (docs/performance.md).
        options = (
            f"-p {self.port} -k {self.folder} -c listen_addresses=127.0.0.1 "
            "-c fsync=off -c synchronous_commit=off -c full_page_writes=off "
            "-c wal_level=minimal -c max_wal_senders=0 -c max_wal_size=1GB "
            "-c checkpoint_timeout=1h -c autovacuum=off"
        )
        self._run("pg_ctl", "-D", str(self.data), "-l", str(self.folder / "log"), "-o", options,
                  "-w", "start")  # fmt: skip

    def stop(self, mode: str = "fast") -> None:
        self._run("pg_ctl", "-D", str(self.data), "-m", mode, "-w", "stop")

    def restart(self) -> None:
        self.stop()
        self.start()

    def url(self, database: str = "postgres") -> str:
        return f"postgresql://sass@127.0.0.1:{self.port}/{database}"

    def create_database(self, name: str, template: str | None = None) -> str:
        """A new database `name` (replacing one of that name): empty, or a copy
        of the database `template` (a file copy on the server, fast; nobody
        may be connected to `template` meanwhile)."""
        import psycopg

        copy = f' TEMPLATE "{template}"' if template else ""
        with psycopg.connect(self.url(), autocommit=True) as conn:
            if template and conn.info.server_version >= 150000:
                # PostgreSQL 15 copies through the WAL by default: 0.20 s for
                # the default database here, against 0.08 s for a file copy
                # (fsync is off, so its checkpoint costs nothing).
                copy += " STRATEGY FILE_COPY"
            conn.execute(f'DROP DATABASE IF EXISTS "{name}" WITH (FORCE)')
            conn.execute(f'CREATE DATABASE "{name}"{copy}')
        return self.url(name)

    def drop_database(self, name: str) -> None:
        import psycopg

        with psycopg.connect(self.url(), autocommit=True) as conn:
            conn.execute(f'DROP DATABASE IF EXISTS "{name}" WITH (FORCE)')

    def remove(self) -> None:
        with contextlib.suppress(subprocess.SubprocessError, OSError):
            self.stop("immediate")
        shutil.rmtree(self.folder, ignore_errors=True)


def _has_user(name: str) -> bool:
    try:
        pwd.getpwnam(name)
    except KeyError:
        return False
    return True


@contextlib.contextmanager
def running_cluster(copy_of: Path | None = None) -> Iterator[Cluster]:
    """A new cluster (initdb's), or one started from a copy of the data folder
    `copy_of` (build_cluster_copy's), stopped and removed at the end."""
    cluster = Cluster()
    try:
        if copy_of is None:
            cluster.init()
        else:  # its databases come with it
            copy_data_folder(copy_of, cluster.data)
        cluster.start()
        yield cluster
    finally:
        cluster.remove()


def build_cluster_copy(data: Path, database: str, fill: Callable[[str], None]) -> None:
    """A cluster's data folder at `data` (a folder that does not exist yet),
    holding `database` after `fill(its address)`, copied from a cluster
    stopped cleanly, for running_cluster(copy_of=data)."""
    with running_cluster() as cluster:
        fill(cluster.create_database(database))
        cluster.stop()
        copy_data_folder(cluster.data, data)


def copy_data_folder(source: Path, target: Path) -> None:
    """A copy of a stopped cluster's data folder at `target` (not there yet)."""
    # cp -a keeps each file's owner (the server's user) and the folder's 0700
    subprocess.run(["cp", "-a", str(source), str(target)], check=True, timeout=120)
