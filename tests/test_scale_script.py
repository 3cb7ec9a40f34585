"""Parameter studies from a plain script, as users write them: no
``if __name__ == '__main__':`` guard, default arguments. The script must
print each result once (workers never re-run it) and end without a Dask
start-up traceback, both when the cost keeps the work in this process and
when a local cluster is asked for."""
import subprocess
import sys
import textwrap

SCRIPT = textwrap.dedent("""
    from sage.all import var
    from sage_dynsym import linearize, stability_map, sweep
    x, y, m, c, k = var('x y m c k')
    osc = linearize([y, -(c*y + k*x)/m], {x: 0, y: 0}, [x, y])
    S = stability_map(osc, {c: (-1, 2, 300), k: (-1, 2, 300)}, fixed={m: 1})
    print("MAP", S.stable().sum())
    W = sweep(lambda a, b: a * b, {'a': (0, 1, 3), 'b': (0, 1, 3)})
    print("SWEEP", W.values().sum())
    T = stability_map(osc, {c: (-1, 2, 30), k: (-1, 2, 30)}, fixed={m: 1}, client='local',
                      workers=1)
    print("LOCAL", T.stable().sum())
""")


def test_plain_script_without_main_guard(tmp_path):
    script = tmp_path / "study.py"
    script.write_text(SCRIPT)
    run = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                         timeout=300, cwd=tmp_path)
    assert run.returncode == 0, run.stderr[-3000:]
    lines = run.stdout.splitlines()
    # stable iff c > 0 and k > 0 (Lienard-Chipart of lambda^2 + c lambda + k): 300 points
    # on [-1, 2] (step 3/299) have 200 positive values on each axis
    assert lines.count("MAP 40000") == 1, run.stdout
    # sum of a*b over a, b in {0, 1/2, 1}: (3/2)^2
    assert lines.count("SWEEP 2.25") == 1, run.stdout
    # 30 points on [-1, 2] (step 3/29): 20 positive values on each axis
    assert lines.count("LOCAL 400") == 1, run.stdout
    assert "Traceback" not in run.stderr, run.stderr[-3000:]
