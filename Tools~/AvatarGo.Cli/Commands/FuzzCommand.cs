using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Threading;
using AvatarGo.Cli.Fuzzing;
using AvatarGo.Core;

namespace AvatarGo.Cli.Commands;

/// <summary>`avatargo fuzz`: seeded mutation fuzzing of the package's parsers, bounded in time.</summary>
public sealed class FuzzCommand : ICommand
{
    public string Name => "fuzz";
    public string Summary => "Fuzz the BVH, session, calibration-profile, controller-profile and JSON parsers";
    public string Help => """
        avatargo fuzz [--target bvh|session|profile|controller|json|all] [--seconds N] [--inputs N] [--seed S] [--corpus DIR]

        Feeds each parser the files of its corpus folder (previous failures), hand-made edge cases (deep
        nesting, huge counts, absurd numbers, long lines), then inputs made by seeded mutation of valid
        files (the package's mocap clips, a simulated session, the profile saved from calibrating it, the
        bundled controller profiles), until N seconds or N inputs have passed. An input fails when the
        parser throws anything but its one-line FormatException, when what it accepted then fails in a
        later stage (poses, humanoid map, restoring and solving a profile, the controller's surface, a
        write/read round trip: an exception, a NaN or infinity), or when it takes more than 1 s. Each
        kind of failure is minimised and saved to the corpus folder as TARGET-HASH.EXT; the default tests
        replay that folder. Parsing runs on a thread with a 1 MB stack, as on Unity's main thread.
          --target T        one parser, or all (default), one after the other
          --seconds N       time budget per target (default 60)
          --inputs N        stop a target after N generated inputs (default: no limit)
          --seed S          mutation seed (default 1); the same seed gives the same inputs
          --corpus DIR      corpus folder (default: the package's Tests/Core/Data~/fuzz-corpus)
          --no-crafted      skip the hand-made edge cases
          --no-minimize     save failures as found
          --slow-ms MS      the time an input may take (default 1000)
          --replay INDEX    run only the INDEX-th generated input (reproduces a crash of the process)
          --out FILE        with --replay: also write that input to FILE
          --trace           print every input's size, time and outcome on standard error
        Exit codes: 0 no failure, 1 failures found, 2 bad arguments, 3 an input hung (saved, run stopped).
        """;

    public int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        var a = new ArgReader(args, "no-crafted", "no-minimize", "trace");
        string target = a.String("target", "all");
        double seconds = a.Double("seconds", 60);
        long inputs = (long)a.Double("inputs", long.MaxValue);
        int seed = a.Int("seed", 1);
        string corpus = a.String("corpus");
        bool crafted = !a.Flag("no-crafted"), minimize = !a.Flag("no-minimize");
        double slowMs = a.Double("slow-ms", 1000);
        string replay = a.String("replay");
        bool trace = a.Flag("trace");
        string outFile = a.String("out");
        a.ThrowOnUnknown(0);
        // At most a million seconds (11.6 days): 1e12, which the option parser allows, overflowed a TimeSpan and aborted the process.
        if (!(seconds > 0 && seconds <= 1e6)) throw new UsageException("--seconds must be positive and at most 1e6");
        if (!(slowMs > 0 && slowMs <= 1e6)) throw new UsageException("--slow-ms must be positive and at most 1e6");
        long replayIndex = -1;
        if (replay != null && !long.TryParse(replay, NumberStyles.None, CultureInfo.InvariantCulture, out replayIndex))
            throw new UsageException($"--replay expects the index of a generated input (0 or more), got '{replay}'");
        if (!(inputs > 0)) throw new UsageException("--inputs must be positive");
        if (outFile != null && replay == null) throw new UsageException("--out goes with --replay");

        var seeds = new FuzzSeeds();
        corpus ??= seeds.DefaultCorpus;
        var options = new FuzzOptions
        {
            Seed = seed, Duration = TimeSpan.FromSeconds(seconds), MaxInputs = inputs, Corpus = corpus,
            Crafted = crafted, Minimize = minimize, SlowMilliseconds = slowMs, Trace = trace,
        };
        string[] targets = target == "all" ? FuzzTargets.Names : new[] { target };
        foreach (string t in targets) FuzzTargets.Create(t, seeds); // rejects an unknown name before any work... and builds the seeds once

        var reports = new List<FuzzReport>();
        int exit = 0;
        // A 1 MB stack, like Unity's main thread on Windows: recursion bounded only by the input shows up here first.
        // What the thread throws is thrown again here, after Join, so that Program reports it (an exception on another
        // thread aborted the process: a --replay --out into a missing folder ended with exit 134).
        Exception failure = null;
        var thread = new Thread(() =>
        {
            try { RunTargets(); }
            catch (Exception e) { failure = e; }
        }, 1 << 20);
        void RunTargets()
        {
            foreach (string t in targets)
            {
                var runner = new FuzzRunner(FuzzTargets.Create(t, seeds), options, stderr);
                if (replay != null)
                {
                    var outcome = runner.Replay(replayIndex, out string input);
                    stdout.WriteLine($"{t} input {replay} of seed {seed} ({input.Length:N0} chars): {(outcome.Bucket == null ? (outcome.Parsed ? "parsed" : "refused with a FormatException") : "FAILS: " + outcome.Description)} in {outcome.Milliseconds:0.0} ms");
                    if (outcome.Bucket != null) exit = 1;
                    if (outFile != null) AtomicFileWriter.WriteAllText(outFile, input);
                    continue;
                }
                stderr.WriteLine($"fuzzing {t} for up to {seconds:0} s (seed {seed}, corpus {corpus})");
                reports.Add(runner.Run());
            }
        }
        thread.Start();
        thread.Join();
        if (failure != null) System.Runtime.ExceptionServices.ExceptionDispatchInfo.Capture(failure).Throw();
        if (replay != null) return exit;

        stdout.WriteLine("target       inputs   generated  parsed   failures  kinds  seconds  inputs/s  slowest ms");
        foreach (FuzzReport r in reports)
        {
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"{r.Target,-10} {r.Inputs,9} {r.Generated,10} {r.Parsed,8} {r.Failures,9} {r.Findings.Count,6} {r.Seconds,8:0.0} {r.Inputs / Math.Max(r.Seconds, 1e-9),9:0} {r.SlowestMilliseconds,11:0.0}"));
            if (r.Failures > 0) exit = 1;
        }
        foreach (FuzzReport r in reports)
            if (r.SlowestInput != null) stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{r.Target}: slowest input {r.SlowestMilliseconds:0.0} ms: {r.SlowestInput}"));
        foreach (FuzzReport r in reports)
            foreach (FuzzFinding f in r.Findings)
            {
                stdout.WriteLine($"{r.Target}: {f.Count} input(s): {f.Bucket}");
                stdout.WriteLine($"    first: {f.Origin}: {f.Description}");
                if (f.SavedAs != null) stdout.WriteLine($"    saved: {f.SavedAs}");
            }
        return exit;
    }
}
