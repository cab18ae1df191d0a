//! The Python package as a user gets it: `pip` builds the wheel from the workspace (maturin)
//! and installs it into a fresh virtual environment with commonroad-io 2024.3; converted
//! corpus scenarios come back as commonroad-io objects (and through the 2026.1 reader too),
//! errors as `osc2cr.ConversionError` with file, line and column, variations as a stream; and
//! the Dask example on two workers writes the very files `osc2cr convert` writes. Closed loop
//! (`osc2cr.Simulation`, `osc2cr.gym`): `closed_loop.rs`; the example a planner author copies,
//! with CommonRoad's tools: `closed_loop_example.rs`.
//!
//! The environment (`target/py/osc2cr-test`) is kept between runs and remade when its
//! requirements change; the wheel is rebuilt every run in this run's own target directory
//! (cargo rebuilds only what changed).

use std::fs::OpenOptions;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

mod closed_loop;
mod closed_loop_example;
mod export;
mod osi;

/// What the test environment holds besides the package (a change remakes the environment);
/// maturin, first, is installed alone before the others, for the wheel.
const REQUIREMENTS: &str = "maturin>=1.7,<2\ncommonroad-io==2024.3\ndask==2026.8.0\ndistributed==2026.8.0\ngymnasium==1.4.0\n";

struct Env {
    /// Interpreter of the fresh environment (commonroad-io 2024.3, dask, osc2cr).
    python: PathBuf,
    /// The package alone (`pip install --target`), to import from another environment.
    package_only: PathBuf,
    /// The abi3 wheel itself, as `maturin build` or `pip wheel .` makes it.
    wheel: PathBuf,
}

static ENV: OnceLock<Result<Env, String>> = OnceLock::new();

fn run(cmd: &mut Command) -> Result<Output, String> {
    let out = cmd.output().map_err(|e| format!("cannot run {cmd:?}: {e}"))?;
    if !out.status.success() {
        return Err(format!("{cmd:?} failed ({}):\n{}{}", out.status, String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr)));
    }
    Ok(out)
}

/// The target directory this test binary was built in (`<target>/<profile>/deps/<exe>`).
fn target_dir() -> Result<PathBuf, String> {
    let exe = std::env::current_exe().map_err(|e| format!("current_exe: {e}"))?;
    exe.ancestors().nth(3).map(Path::to_path_buf).ok_or_else(|| format!("{} is not under <target>/<profile>/deps", exe.display()))
}

fn setup() -> Result<Env, String> {
    let root = testkit::workspace_root();
    let py = root.join("target/py");
    std::fs::create_dir_all(&py).map_err(|e| format!("cannot create {}: {e}", py.display()))?;
    let lock_path = root.join("target/py-osc2cr.lock");
    let lock = OpenOptions::new().create(true).truncate(false).write(true).open(&lock_path).map_err(|e| format!("cannot open {}: {e}", lock_path.display()))?;
    lock.lock().map_err(|e| format!("cannot lock {}: {e}", lock_path.display()))?;

    let venv = py.join("osc2cr-test");
    let bin = venv.join("bin");
    let python = bin.join("python");
    let stamp = venv.join(".ready");
    let fresh = std::fs::read_to_string(&stamp).ok().as_deref() != Some(REQUIREMENTS);
    if fresh {
        let _ = std::fs::remove_dir_all(&venv);
        run(Command::new("python3").args(["-m", "venv"]).arg(&venv))?;
        // maturin first: the wheel below needs only it
        let maturin = REQUIREMENTS.lines().next().unwrap_or_default();
        run(Command::new(&python).args(["-m", "pip", "install", "--quiet", "--disable-pip-version-check", maturin]))?;
    }

    // `pip wheel .` as a user's `pip install .` does it (maturin from the environment),
    // compiling into this run's target directory so that built crates are reused; in a fresh
    // environment the other requirements install meanwhile (pip unpacks on one core while
    // cargo builds on the others)
    let wheels = py.join("osc2cr-wheel");
    let _ = std::fs::remove_dir_all(&wheels);
    let path = format!("{}:{}", bin.display(), std::env::var("PATH").unwrap_or_default());
    let target = target_dir()?;
    let (built, installed) = std::thread::scope(|scope| {
        let rest = scope.spawn(|| -> Result<(), String> {
            if !fresh {
                return Ok(());
            }
            let req = venv.join("requirements.txt");
            std::fs::write(&req, REQUIREMENTS).map_err(|e| e.to_string())?;
            run(Command::new(&python).args(["-m", "pip", "install", "--quiet", "--disable-pip-version-check", "-r"]).arg(&req))?;
            std::fs::write(&stamp, REQUIREMENTS).map_err(|e| e.to_string())
        });
        let built = run(Command::new(&python)
            .args(["-m", "pip", "wheel", "--quiet", "--disable-pip-version-check"])
            .args(["--no-deps", "--no-build-isolation", "-w"])
            .arg(&wheels)
            .arg(&root)
            .env("PATH", &path)
            .env("CARGO_TARGET_DIR", &target));
        (built, rest.join().unwrap_or_else(|_| Err("the requirements' thread panicked".into())))
    });
    installed?;
    built?;
    let wheel = std::fs::read_dir(&wheels)
        .map_err(|e| e.to_string())?
        .flatten()
        .map(|e| e.path())
        .find(|p| p.extension().is_some_and(|x| x == "whl"))
        .ok_or("pip wheel made no wheel")?;
    run(Command::new(&python).args(["-m", "pip", "install", "--quiet", "--disable-pip-version-check"]).args(["--no-deps", "--force-reinstall"]).arg(&wheel))?;
    let package_only = py.join("osc2cr-only");
    let _ = std::fs::remove_dir_all(&package_only);
    run(Command::new(&python)
        .args(["-m", "pip", "install", "--quiet", "--disable-pip-version-check", "--no-deps", "--target"])
        .arg(&package_only)
        .arg(&wheel))?;
    drop(lock);
    Ok(Env { python, package_only, wheel })
}

/// The environment, or `None` (with a notice) when the shared corpus is absent outside CI.
fn env() -> Option<&'static Env> {
    testkit::shared_dir()?;
    match ENV.get_or_init(setup) {
        Ok(e) => Some(e),
        Err(e) => panic!("cannot prepare the Python package: {e}"),
    }
}

/// A scratch directory removed when the test passes (a wheel's venv is ~440 MB).
fn tmp(name: &str) -> testkit::ScratchDir {
    testkit::ScratchDir::new(&format!("py-{name}"))
}

fn corpus(rel: &str) -> PathBuf {
    testkit::shared_dir().expect("shared").join("corpus").join(rel)
}

fn python(interpreter: &Path, script: &str, args: &[&Path]) -> String {
    let out = Command::new(interpreter).arg("-c").arg(script).args(args).output().expect("python runs");
    assert!(out.status.success(), "python failed:\n{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn osc2cr_convert(inputs: &[&Path], out: &Path) {
    let r = Command::new(env!("CARGO_BIN_EXE_osc2cr")).arg("convert").args(inputs).arg("-o").arg(out).output().expect("osc2cr runs");
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
}

/// Counts `<tag ` / `<tag>` openings in CommonRoad XML text.
fn count(xml: &str, tag: &str) -> usize {
    xml.matches(&format!("<{tag} ")).count() + xml.matches(&format!("<{tag}>")).count()
}

const READ: &str = r#"
import sys, warnings
import osc2cr
warnings.simplefilter("ignore", osc2cr.ConversionWarning)
path, cli_xml = sys.argv[1], sys.argv[2]
xml = osc2cr.convert_to_xml(path)
assert xml == open(cli_xml, encoding="utf-8").read(), "convert_to_xml differs from the CLI's file"
scenario, problems = osc2cr.convert(path)
print(type(scenario).__name__, type(problems).__name__)
print(len(scenario.dynamic_obstacles), len(scenario.static_obstacles), len(scenario.environment_obstacle))
print(len(scenario.lanelet_network.lanelets), len(problems.planning_problem_dict))
print(scenario.dt, str(scenario.scenario_id))
"#;

#[test]
fn a_fresh_environment_reads_a_converted_corpus_scenario_as_commonroad_objects() {
    let Some(env) = env() else { return };
    let file = corpus("esmini/xosc/cut-in.xosc");
    let out = tmp("read");
    osc2cr_convert(&[&file], &out);
    let cli_xml = out.join("cut-in.xml");
    let text = std::fs::read_to_string(&cli_xml).expect("CLI output");
    let expected = format!(
        "Scenario PlanningProblemSet\n{} {} {}\n{} {}\n",
        count(&text, "dynamicObstacle"),
        count(&text, "staticObstacle"),
        count(&text, "environmentObstacle"),
        count(&text, "lanelet"),
        count(&text, "planningProblem"),
    );
    let got = python(&env.python, READ, &[&file, &cli_xml]);
    assert!(got.starts_with(&expected), "got:\n{got}\nexpected the CLI file's counts:\n{expected}");
    assert!(count(&text, "dynamicObstacle") >= 2, "the cut-in has an ego and a target");
    // dt and benchmark id as written in the header
    assert!(got.contains("0.1 ZAM_cutin-1_1_T-1"), "{got}");
    assert!(text.contains(r#"benchmarkID="ZAM_cutin-1_1_T-1""#));

    // commonroad-io 2026.1 (the other reader API) reads it too, through the same function
    let cr = testkit::python_envs().expect("python envs").cr;
    let script = format!("import sys; sys.path.insert(0, {:?})\n{READ}", env.package_only.display().to_string());
    let got26 = python(&cr, &script, &[&file, &cli_xml]);
    assert!(got26.starts_with(&expected), "2026.1 reader:\n{got26}");
}

const FORMAT_2024: &str = r#"
import sys, os, warnings, tempfile
import osc2cr
warnings.simplefilter("ignore", osc2cr.ConversionWarning)
path, dist, cli_dir = sys.argv[1], sys.argv[2], sys.argv[3]
files = osc2cr.convert_to_protobuf(path)
cli = lambda name: open(os.path.join(cli_dir, name), "rb").read()
stem = osc2cr.output_name(path, format="2024")[: -len("-SC.pb")]
print("bytes", files.scenario == cli(stem + "-SC.pb"), files.dynamic == cli(stem + ".pb"), files.map == cli(files.map_id + ".pb"))
scenario, problems = osc2cr.convert(path, format="2024")
s20, p20 = osc2cr.convert(path)
print("objects", len(scenario.dynamic_obstacles) == len(s20.dynamic_obstacles), len(scenario.lanelet_network.lanelets) == len(s20.lanelet_network.lanelets),
      list(problems.planning_problem_dict) == list(p20.planning_problem_dict), str(scenario.scenario_id) == str(s20.scenario_id))
out = tempfile.mkdtemp()
written = files.write(out, stem)
s2, _ = osc2cr.read_protobuf_files(written[0])
print("written", [os.path.basename(p) for p in written] == [stem + "-SC.pb", stem + ".pb", files.map_id + ".pb"], len(s2.dynamic_obstacles) == len(s20.dynamic_obstacles))
vs = list(osc2cr.variations(dist, stop=3, format="2024"))
print("variations", len(vs), vs[0].xml is None, vs[0].protobuf.map_id == vs[1].protobuf.map_id, vs[0].protobuf.dynamic != vs[1].protobuf.dynamic)
try:
    osc2cr.convert_to_xml(path, format="2024")
except ValueError:
    print("xml refuses 2024")
"#;

const ERRORS: &str = r#"
import sys, pickle, itertools, warnings
import osc2cr
warnings.simplefilter("ignore", osc2cr.ConversionWarning)
bad, dist, missing, example = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
try:
    osc2cr.convert_to_xml(bad)
    raise SystemExit("no error for a malformed file")
except osc2cr.ConversionError as e:
    print("malformed", e.file == bad, e.line, e.column is not None and e.column >= 1, e.stage)
    e2 = pickle.loads(pickle.dumps(e))
    print("pickled", (e2.file, e2.line, e2.column) == (e.file, e.line, e.column))
try:
    osc2cr.convert_to_xml(missing)
except FileNotFoundError as e:
    print("missing", isinstance(e, osc2cr.ConversionError), e.file == missing, e.line, missing in str(e), "no such file" in str(e).lower(), "schema" in str(e))
try:
    osc2cr.convert_to_xml(bad, no_such_option=1)
except TypeError:
    print("typeerror")
try:
    osc2cr.convert_to_xml(bad, dt=-1.0)
except ValueError:
    print("valueerror")
print("count", osc2cr.count_variations(dist), osc2cr.count_variations(dist, max_variations=5))
for v in itertools.islice(osc2cr.variations(dist), 2):
    print("variation", v.index, sorted(v.parameters.items()))
last = next(osc2cr.variations(dist, start=12))
print("last", last.index, sorted(last.parameters.items()))
try:
    osc2cr.convert_to_xml(example, params={"EgoSpeeed": 10})
    print("strict: converted")
except osc2cr.ConversionError as e:
    print("strict:", "EgoSpeeed" in str(e), "lenient=True" in str(e), "--" in str(e))
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always", osc2cr.ConversionWarning)
    xml = osc2cr.convert_to_xml(example, params={"EgoSpeeed": 10}, lenient=True)
    print("lenient:", xml.startswith("<?xml"), any("EgoSpeeed" in str(w.message) for w in caught))
"#;

#[test]
fn the_2024_format_comes_as_the_cli_files_and_reads_with_commonroad_io_2026() {
    let Some(env) = env() else { return };
    let file = corpus("esmini/xosc/cut-in.xosc");
    let dist = corpus("esmini/xosc/cut-in_parameter_set.xosc");
    let out = tmp("format-2024");
    let r = Command::new(env!("CARGO_BIN_EXE_osc2cr")).args(["convert", s(&file), "-o", s(&out), "--format", "2024"]).output().expect("osc2cr runs");
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    // the three-file reader is commonroad-io 2026's
    let cr = testkit::python_envs().expect("python envs").cr;
    let script = format!("import sys; sys.path.insert(0, {:?})\n{FORMAT_2024}", env.package_only.display().to_string());
    let got = python(&cr, &script, &[&file, &dist, &out]);
    let lines: Vec<&str> = got.lines().collect();
    assert_eq!(lines, ["bytes True True True", "objects True True True True", "written True True", "variations 2 True True True", "xml refuses 2024"], "{got}");
}

fn s(p: &Path) -> &str {
    p.to_str().expect("utf-8 path")
}

#[test]
fn errors_carry_file_line_and_column_and_variations_stream() {
    let Some(env) = env() else { return };
    let dir = tmp("errors");
    let bad = dir.join("bad.xosc");
    // line 3 holds an element that is never closed
    std::fs::write(&bad, "<OpenSCENARIO>\n  <FileHeader/>\n  <Storyboard><Init>\n</OpenSCENARIO>\n").expect("write");
    let dist = corpus("esmini/xosc/cut-in_parameter_set.xosc");
    let missing = dir.join("missing.xosc");
    let example = testkit::workspace_root().join("examples/cut_in.xosc");
    let got = python(&env.python, ERRORS, &[&bad, &dist, &missing, &example]);
    let lines: Vec<&str> = got.lines().collect();
    // the mismatch is seen at the closing tag on line 4
    assert_eq!(lines[0], "malformed True 4 True load", "{got}");
    assert_eq!(lines[1], "pickled True");
    // a scenario file that is not there: a FileNotFoundError (and a ConversionError), saying so
    assert_eq!(lines[2], "missing True True None True True False", "{got}");
    assert_eq!(lines[3], "typeerror");
    assert_eq!(lines[4], "valueerror");
    // the distribution: {2 value sets} × {70, 110} × range 1.1..1.5 step 0.2 (3) = 12 runs,
    // in odometer order (last factor fastest)
    assert_eq!(lines[5], "count 12 5");
    let first = "('EgoSpeed', '70.0'), ('HostVehicle', 'car_blue'), ('TargetSpeedFactor', '1.1'), ('TargetVehicle', 'car_yellow')";
    let second = "('EgoSpeed', '70.0'), ('HostVehicle', 'car_blue'), ('TargetSpeedFactor', '1.3'), ('TargetVehicle', 'car_yellow')";
    assert_eq!(lines[6], format!("variation 1 [{first}]"));
    assert_eq!(lines[7], format!("variation 2 [{second}]"));
    assert_eq!(lines[8], "last 12 [('EgoSpeed', '110.0'), ('TargetSpeedFactor', '1.5'), ('TargetVehicle', 'van_red')]");
    // strict by default: an override of a parameter the scenario does not declare is an error;
    // lenient=True converts and says so as a ConversionWarning
    // the message names the option as Python spells it, never the command line's --lenient
    assert_eq!(lines[9], "strict: True True False", "{got}");
    assert_eq!(lines[10], "lenient: True True", "{got}");
}

#[test]
fn the_dask_example_on_two_workers_writes_the_cli_files() {
    let Some(env) = env() else { return };
    let dist = corpus("esmini/xosc/cut-in_parameter_set.xosc");
    for format in ["2020a", "2024"] {
        let (cli, dask) = (tmp(&format!("dask-cli-{format}")), tmp(&format!("dask-out-{format}")));
        let r = Command::new(env!("CARGO_BIN_EXE_osc2cr")).args(["convert", s(&dist), "-o", s(&cli), "--format", format]).output().expect("osc2cr runs");
        assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
        let example = testkit::workspace_root().join("examples/dask_variations.py");
        let out =
            Command::new(&env.python).arg(&example).arg(&dist).arg("-o").arg(&dask).args(["--workers", "2", "--format", format]).output().expect("python runs");
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let report = String::from_utf8_lossy(&out.stdout);
        assert!(report.contains(r#""variations": 12"#) && report.contains(r#""workers": 2"#), "{report}");
        let names = |d: &Path| {
            let mut v: Vec<PathBuf> = std::fs::read_dir(d).expect("dir").flatten().map(|e| e.path()).collect();
            v.sort();
            v
        };
        let (a, b) = (names(&cli), names(&dask));
        // 12 XML files, or 12 scenario and 12 dynamic files and their one map
        assert_eq!(a.len(), if format == "2020a" { 12 } else { 25 }, "{a:?}");
        assert_eq!(a.iter().map(|p| p.file_name()).collect::<Vec<_>>(), b.iter().map(|p| p.file_name()).collect::<Vec<_>>());
        for (x, y) in a.iter().zip(&b) {
            assert!(std::fs::read(x).ok() == std::fs::read(y).ok(), "{} differs", y.display());
        }
    }
}

/// The first ```python block of the README's section `heading`, as a user would copy it.
fn readme_example(heading: &str) -> String {
    let readme = std::fs::read_to_string(testkit::workspace_root().join("README.md")).expect("README");
    let section = readme.split(&format!("\n## {heading}\n")).nth(1).unwrap_or_else(|| panic!("a section {heading}"));
    let block = section.split("```python\n").nth(1).expect("a python block");
    block.split("\n```").next().expect("closed").to_string()
}

// named to start among the first of this binary's Python tests (libtest starts them in name
// order): its own environment takes a minute, which the others then share the cores with
#[test]
fn a_wheel_installs_without_rust_and_runs_the_readme_example() {
    let Some(env) = env() else { return };
    let name = env.wheel.file_name().and_then(|n| n.to_str()).unwrap_or_default().to_string();
    // one wheel for every CPython >= 3.9
    assert!(name.contains("-abi3-"), "{name} is not an abi3 wheel");

    // a fresh environment, and a PATH that has Python but no Rust toolchain
    let dir = tmp("wheel");
    let venv = dir.join("venv");
    let status = Command::new("python3").args(["-m", "venv"]).arg(&venv).status().expect("venv");
    assert!(status.success());
    let bin = venv.join("bin");
    let path = format!("{}:/usr/local/bin:/usr/bin:/bin", bin.display());
    let pip = |args: &[&str]| {
        let out = Command::new(bin.join("python"))
            .args(["-m", "pip", "install", "--quiet", "--disable-pip-version-check"])
            .args(args)
            .env("PATH", &path)
            .env_remove("CARGO_HOME")
            .env_remove("RUSTUP_HOME")
            .output()
            .expect("pip runs");
        assert!(out.status.success(), "pip install {args:?}:\n{}", String::from_utf8_lossy(&out.stderr));
    };
    let wheel = env.wheel.display().to_string();
    pip(&[&format!("{wheel}[commonroad]"), "commonroad-io==2024.3"]);

    // the README's example, run as written from a folder holding the repository's examples
    let work = dir.join("work");
    std::fs::create_dir_all(work.join("examples")).expect("mkdir");
    for f in ["cut_in.xosc", "cut_in_speeds.xosc", "two_lane_curve.xodr"] {
        std::fs::copy(testkit::workspace_root().join("examples").join(f), work.join("examples").join(f)).expect("copy example");
    }
    let script = format!(
        "import shutil\nassert shutil.which('cargo') is None and shutil.which('rustc') is None, 'Rust on PATH'\n{}\nprint('example ran', len(scenario.dynamic_obstacles), len(xml) > 0)\n",
        readme_example("Python")
    );
    let out = Command::new(bin.join("python"))
        .arg("-c")
        .arg(&script)
        .current_dir(&work)
        .env("PATH", &path)
        .env_remove("CARGO_HOME")
        .env_remove("RUSTUP_HOME")
        .output()
        .expect("python runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "the README example failed:\n{stdout}{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("example ran 3 True"), "{stdout}");
    // the sweep's six variations were written into out/, as `osc2cr convert` names them, and
    // nothing beside the examples
    for k in 1..=6 {
        let f = work.join(format!("out/cut_in_speeds_{k}.xml"));
        let text = std::fs::read_to_string(&f).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        assert!(text.contains("<commonRoad"), "{}", f.display());
    }
    let mut top: Vec<String> = std::fs::read_dir(&work).expect("work").flatten().map(|e| e.file_name().to_string_lossy().into_owned()).collect();
    top.sort();
    assert_eq!(top, ["examples", "out"]);
}

#[test]
fn the_readme_closed_loop_example_runs() {
    let Some(env) = env() else { return };
    let work = tmp("readme-closed-loop");
    std::fs::create_dir_all(work.join("examples")).expect("mkdir");
    for f in ["cut_in.xosc", "two_lane_curve.xodr"] {
        std::fs::copy(testkit::workspace_root().join("examples").join(f), work.join("examples").join(f)).expect("copy example");
    }
    let script = format!("import warnings, osc2cr\nwarnings.simplefilter('ignore', osc2cr.ConversionWarning)\n{}\n", readme_example("Closed loop from Python"));
    let out = Command::new(&env.python).arg("-c").arg(&script).current_dir(&work).output().expect("python runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "the README's closed-loop example failed:\n{stdout}{}", String::from_utf8_lossy(&out.stderr));
    // the CutIn event started, and the three road users are in the output
    let printed: Vec<&str> = stdout.split_whitespace().collect();
    assert!(printed.first().and_then(|t| t.parse::<f64>().ok()).is_some_and(|t| t > 0.0), "{stdout}");
    assert_eq!(printed.get(1), Some(&"3"), "{stdout}");
    let gif = std::fs::read(work.join("out/run.gif")).expect("out/run.gif written");
    assert!(gif.starts_with(b"GIF89a"), "not a GIF");
}
