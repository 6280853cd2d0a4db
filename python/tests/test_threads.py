"""The GIL is released during file reads and schemes, and an editor shared by threads stays consistent."""

import os
import threading

from meshes import torus_arrays

import dlfl


def through_a_pipe(path, text, read):
    """read(path) on another thread, path a named pipe that this thread writes `text` into: with the GIL held
    during the read, this thread could never run, and the test would hang (CTest's timeout) instead of
    passing."""
    os.mkfifo(path)
    result = []
    reader = threading.Thread(target=lambda: result.append(read(path)))
    reader.start()
    with open(path, "w") as pipe:
        pipe.write(text)
    reader.join()
    return result[0]


def test_read_mesh_releases_the_gil(data, tmp_path):
    mesh = through_a_pipe(tmp_path / "cube.obj", (data / "cube.obj").read_text(), dlfl.read_mesh)
    assert mesh == dlfl.read_mesh(data / "cube.obj")


def test_replaying_a_log_file_releases_the_gil(data, tmp_path):
    ed = dlfl.Editor(dlfl.read_mesh(data / "cube.obj"))
    ed.insert_edge(0, 2)
    log = tmp_path / "session.json"
    ed.write_log(log)
    assert through_a_pipe(tmp_path / "pipe.json", log.read_text(), dlfl.replay).mesh == ed.mesh


def test_schemes_on_threads_give_what_they_give_alone():
    positions, faces = torus_arrays(24, 16)
    meshes = [dlfl.Mesh.from_arrays(positions * (k + 1), faces) for k in range(4)]
    alone = [dlfl.subdivide(m, "catmull-clark", iterations=2).hash() for m in meshes]
    results = [None] * 4

    def work(k):
        results[k] = dlfl.subdivide(meshes[k], "catmull-clark", iterations=2).hash()

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results == alone


def test_an_editor_shared_by_threads_applies_every_operation_once():
    positions, faces = torus_arrays(20, 10)
    ed = dlfl.Editor(dlfl.Mesh.from_arrays(positions, faces))
    live = ed.mesh

    def split(first):
        # The diagonals of faces first, first + 2, ...: corners 4f and 4f + 2 of face f.
        for f in range(first, 200, 2):
            ed.insert_edge(4 * f, 4 * f + 2)

    threads = [threading.Thread(target=split, args=(k,)) for k in (0, 1)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    # Every face split once, whatever the interleaving: E + 200, F + 200.
    assert (live.num_vertices, live.num_edges, live.num_faces) == (200, 600, 400)
    assert dlfl.validate(live)["valid"] and len(ed.undo_history()) == 201


def test_a_subdivision_on_another_thread_is_seen_whole_or_not_at_all():
    positions, faces = torus_arrays(32, 16)
    ed = dlfl.Editor(dlfl.Mesh.from_arrays(positions, faces))
    live = ed.mesh
    worker = threading.Thread(target=lambda: ed.subdivide("catmull-clark", iterations=3))
    seen = set()
    worker.start()
    while worker.is_alive():
        seen.add((live.num_vertices, live.num_faces))  # waits for the editor while the scheme runs
    worker.join()
    seen.add((live.num_vertices, live.num_faces))
    # Catmull-Clark on a closed quad torus: F' = 4F, V' = V + E + F = 4V (E = 2F = 2V): 512 -> 32768.
    assert seen <= {(512, 512), (32768, 32768)} and (32768, 32768) in seen
