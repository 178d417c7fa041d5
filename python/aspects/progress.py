"""Progress of aspects.solve: tqdm when installed, else a line on stderr now and then."""
import sys
import time


def _describe(d):
    where = f"phase done: {d['phases'][-1][0]}" if d["phases"] else "searching"
    return (f"{d['processed']} boxes, {d['solutions']} solution, {d['undecided']} undecided, "
            f"{100 * d['decided']:.1f}% of the domain decided ({where})")


class _Tqdm:
    def __init__(self, tqdm):
        self.bar = tqdm(total=100, unit="%", desc="aspects", bar_format=(
            "{desc}: {percentage:3.0f}% of the domain decided |{bar}| {elapsed} {postfix}"))
        self.last = 0.0

    def __call__(self, d):
        share = 100 * min(1.0, max(0.0, d["decided"]))
        if share > self.last:
            self.bar.update(share - self.last)
            self.last = share
        self.bar.set_postfix_str(f"{d['processed']} boxes, {d['solutions']} solution",
                                 refresh=True)

    def close(self):
        self.bar.close()


class _Lines:
    """One line every 2 s on stderr (a notebook shows stderr too)."""

    def __init__(self):
        self.next = 0.0
        self.last = None

    def __call__(self, d):
        self.last = d
        now = time.monotonic()
        if now >= self.next:
            self.next = now + 2.0
            print(f"[aspects] {_describe(d)}", file=sys.stderr, flush=True)

    def close(self):
        if self.last is not None:
            print(f"[aspects] done: {_describe(self.last)}", file=sys.stderr, flush=True)


def progress_callback(progress):
    """(callback for the compiled solve, or None; a function to call when it ends)."""
    if progress is None or progress is False:
        return None, lambda: None
    if callable(progress):
        return progress, lambda: None
    if progress is True:
        try:
            from tqdm import tqdm
            shown = _Tqdm(tqdm)
        except ImportError:
            shown = _Lines()
        return shown, shown.close
    raise TypeError("progress must be None, True or a callable taking a dict")
