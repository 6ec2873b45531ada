"""tests/corpus.py finds the external corpus from a git worktree outside the main checkout's folder."""

from __future__ import annotations

from tests.corpus import _beside_main_checkout


def test_a_worktree_finds_the_corpus_beside_its_main_checkout(tmp_path):
    main, tree = tmp_path / "work" / "main", tmp_path / "elsewhere" / "wt" / "x"
    (main / ".git" / "worktrees" / "x").mkdir(parents=True)
    tree.mkdir(parents=True)
    (tree / ".git").write_text(f"gitdir: {main / '.git' / 'worktrees' / 'x'}\n", encoding="utf-8")
    assert _beside_main_checkout(tree) == (tmp_path / "work" / "shared" / "corpus").resolve()


def test_a_relative_gitdir_and_a_plain_checkout(tmp_path):
    main, tree = tmp_path / "main", tmp_path / "main" / "trees" / "y"
    (main / ".git" / "worktrees" / "y").mkdir(parents=True)
    tree.mkdir(parents=True)
    (tree / ".git").write_text("gitdir: ../../.git/worktrees/y\n", encoding="utf-8")
    assert _beside_main_checkout(tree) == (tmp_path / "shared" / "corpus").resolve()
    assert _beside_main_checkout(main) is None  # its .git is a folder
