using System;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Json;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Issue 29's measure of the bake's locking on the nine files of the feet issue (LaFAN1 fallAndGetUp1, ground1,
    /// obstacles1 of subject 5; held-out CMU 02_01, 02_02, 09_12, 38_01, 38_02, 38_03), keys every 15 and 30 model
    /// frames, default model, as <c>bake</c> runs them (<see cref="InbetweenBake"/>; CMU files from frame 1 with frame 0
    /// as the reference, cmu-more files from frame 10): skating off, locked (the one contact source: the model's
    /// predicted contacts where it has them, labelled otherwise), locked with labelled contacts only, and locked with the
    /// truth's own contacts (the bound that separates contact timing from motion) in place of the labels and added to
    /// them (the truth's contacts are the labels the network learns: each foot joint from its own ground level,
    /// <see cref="FootSkating.ContactLabels"/>); with an exported experimental classifier
    /// (<see cref="FilledMotionContactClassifier"/>, issue 29's second session) also its precision and recall on the
    /// filled rig frames and the locks with its contacts; position error locked ÷ off, weighted
    /// by non-key frames; planted joints' height against where they are held; keys unchanged. Nothing is chosen by these
    /// files: it only measures. Explicit: ~2–4 minutes on a loaded machine
    /// (<c>dotnet test Tools~/Tests/DeltaInterpolator.Tests.csproj --filter FullyQualifiedName~FootContactMeasureTests</c>).
    /// </summary>
    [TestFixture]
    [Explicit("measurement for issue 29's closing note: minutes of model bakes on nine files")]
    public sealed class FootContactMeasureTests
    {
        private static readonly string[] Files =
        {
            "lafan1/fallAndGetUp1_subject5", "lafan1/ground1_subject5", "lafan1/obstacles1_subject5",
            "cmu/02_01", "cmu/02_02", "cmu/09_12", "cmu-more/38_01", "cmu-more/38_02", "cmu-more/38_03",
        };

        [TestCase(15)]
        [TestCase(30)]
        public void NineFilesLockedWithTheContactSource(int modelFrames) => Measure(Files, modelFrames, "nine files");

        /// <summary>
        /// The measure over <paramref name="files"/> (paths under the data folder without ".bvh"; "cmu/" files from frame 1
        /// with frame 0 as the reference, "cmu-more/" files from frame 10, others from frame 0), keys every
        /// <paramref name="modelFrames"/> model frames; prints the table and asserts only that locking helps.
        /// </summary>
        internal static void Measure(string[] files, int modelFrames, string title)
        {
            string lafan = TestEnvironment.RequireLafan1();
            string data = Path.GetDirectoryName(lafan)!;
            // The default model (CMU), as issue 29 measures it.
            string defaultModel = ShippedModelTests.RequireDefaultModel();
            using Inbetweener model = OnnxRuntimeInbetweener.Load(defaultModel);
            FilledMotionContactClassifier? classifier = Classifier();
            var totals = new Totals();
            foreach (string name in files)
            {
                string file = Path.Combine(data, name + ".bvh");
                if (!File.Exists(file)) Assert.Ignore($"{file} not found; skipping.");
                MotionClip truth = BvhReader.Read(file).Motion;
                bool cmu = name.StartsWith("cmu/", StringComparison.Ordinal), more = name.StartsWith("cmu-more/", StringComparison.Ordinal);
                int ratio = (int)Math.Round(1.0 / (model.Contract.FramesPerSecond * truth.FrameTime));
                int[] keys = BakeKeys.Every(modelFrames * ratio, truth, cmu ? 1 : more ? 10 : 0, model.Contract);
                IRigRetargeting rig = RigRetargeting.For(model.Contract, truth, file, cmu ? 0 : (int?)null, null);
                BakeRun off = InbetweenBake.Run(truth, keys, rig, new[] { BakeMethod.Model(model) });
                BakeRun on = InbetweenBake.Run(truth, keys, rig, new[] { BakeMethod.Model(model, feet: new FootLockSettings()) });
                FootRig feet = BakeScores.Feet(off, truth.Skeleton);
                MotionClip offClip = off.Methods[0].OnRig, lockedClip = on.Methods[0].OnRig;
                AssertKeysUnchanged(offClip, lockedClip, keys, name);

                var relative = new int[keys.Length];
                for (int i = 0; i < keys.Length; i++) relative[i] = keys[i] - keys[0];
                MotionClip labelledClip = Copy(offClip), knownClip = Copy(offClip), sourcedClip = Copy(offClip);
                new FootLocker(feet, new FootLockSettings()).Lock(labelledClip, relative);
                double[] truthFeet = FootSkating.FootPositions(truth, keys[0], offClip.FrameCount, feet.FootJoints);
                // The truth's contacts as the network learns them: each foot joint from its own ground level (the ankles too).
                bool[] planted = FootSkating.ContactLabels(truthFeet, feet.FootJoints.Count, truth.FrameTime, feet.LegLength);
                new FootLocker(feet, new FootLockSettings()).LockWithContacts(knownClip, relative, Channels(planted, feet, offClip.FrameCount));
                // The bake's own lock again, by hand, to read where it holds each planted joint (its result is the bake's, checked below).
                var contacts = new FootContacts();
                off.Methods[0].Contacts.ResampleInto(contacts, offClip.FrameCount, offClip.FrameTime, off.Methods[0].OnModel.FrameTime,
                    keys[0] * truth.FrameTime - off.ModelKeys[0] * off.Methods[0].OnModel.FrameTime);
                var sourced = new FootLocker(feet, new FootLockSettings());
                sourced.Lock(sourcedClip, relative, contacts);
                Assert.That(Max(sourcedClip.LocalRotations, lockedClip.LocalRotations), Is.LessThan(1e-9), $"{name}: the by-hand lock is the bake's");

                // The truth's contacts added to the locker's own labels (rather than in their place): how far contact
                // timing alone takes today's locker when the labels it finds by itself are kept.
                bool[] truthChannels = Channels(planted, feet, offClip.FrameCount);
                int samples = FootSkating.OfTruth(truth, keys, feet).ContactSamples;
                MotionClip truthAddedClip = LockedWithLabelsAnd(offClip, relative, feet, (f, c) => truthChannels[f * FootLocker.ChannelCount + c]);
                if (samples > 0) totals.TruthAdded += samples * FootSkating.Measure(truth, truthAddedClip, keys, feet).MeanSpeed;
                string classified = "";
                if (classifier != null)
                {
                    // The experimental classifier's contacts on the model's frames, to the rig's as the bake takes the model's.
                    FootContacts onRig = Classify(classifier, off, offClip, keys[0] * truth.FrameTime);
                    int hits = 0, said = 0, actual = 0;
                    for (int f = 0; f < offClip.FrameCount; f++)
                    {
                        if (!onRig.IsPredicted(f)) continue;
                        for (int c = 0; c < FootLocker.ChannelCount; c++)
                        {
                            bool guess = onRig.IsPlanted(f, c), known = truthChannels[f * FootLocker.ChannelCount + c];
                            hits += guess && known ? 1 : 0;
                            said += guess ? 1 : 0;
                            actual += known ? 1 : 0;
                        }
                    }

                    totals.ClassifierHits += hits;
                    totals.ClassifierSaid += said;
                    totals.ClassifierActual += actual;
                    MotionClip classifiedClip = Copy(offClip);
                    new FootLocker(feet, new FootLockSettings()).Lock(classifiedClip, relative, onRig);
                    AssertKeysUnchanged(offClip, classifiedClip, keys, name);
                    MotionClip addedClip = LockedWithLabelsAnd(offClip, relative, feet, (f, c) => onRig.IsPredicted(f) && onRig.IsPlanted(f, c));
                    double speed = FootSkating.Measure(truth, classifiedClip, keys, feet).MeanSpeed, added = FootSkating.Measure(truth, addedClip, keys, feet).MeanSpeed;
                    if (samples > 0)
                    {
                        totals.Classified += samples * speed;
                        totals.ClassifierAdded += samples * added;
                    }

                    classified = $"; classifier P {(double)hits / Math.Max(said, 1):F3} R {(double)hits / Math.Max(actual, 1):F3}, its contacts {speed:F3}, added to the labels {added:F3}";
                }

                FootSkating truthSkating = FootSkating.OfTruth(truth, keys, feet);
                int frames = BakeAccuracy.Measure(truth, offClip, keys).Frames;
                totals.Add(truthSkating, FootSkating.Measure(truth, offClip, keys, feet), FootSkating.Measure(truth, lockedClip, keys, feet),
                    FootSkating.Measure(truth, labelledClip, keys, feet), FootSkating.Measure(truth, knownClip, keys, feet),
                    BakeAccuracy.Measure(truth, offClip, keys).MeanPositionError / feet.LegLength, BakeAccuracy.Measure(truth, lockedClip, keys).MeanPositionError / feet.LegLength, frames);
                HeightHold(sourced, sourcedClip, feet, relative, totals);
                double offAcceleration = Acceleration(offClip, feet), lockedAcceleration = Acceleration(lockedClip, feet);
                totals.OffAcceleration += offAcceleration;
                totals.LockedAcceleration += lockedAcceleration;
                totals.TruthAcceleration += Acceleration(Frames(truth, keys[0], offClip.FrameCount), feet);
                TestContext.Out.WriteLine($"  {name}: truth {truthSkating.MeanSpeed:F3}, off {totals.LastOff:F3}, locked {totals.LastLocked:F3}, labelled {totals.LastLabelled:F3}, truth's contacts {totals.LastKnown:F3}, added to the labels {FootSkating.Measure(truth, truthAddedClip, keys, feet).MeanSpeed:F3}, foot acceleration locked ÷ off {lockedAcceleration / offAcceleration:F2}{classified}");
            }

            double truthMean = totals.Truth / totals.Samples, offMean = totals.Off / totals.Samples, lockedMean = totals.Locked / totals.Samples;
            double labelledMean = totals.Labelled / totals.Samples, knownMean = totals.Known / totals.Samples;
            double error = totals.LockedError / totals.OffError;
            string contactsFrom = model.Contract.HasFootContacts ? "predicted" : "labelled (the model has no contact output)";
            TestContext.Out.WriteLine($"keys every {modelFrames} model frames, {title}, {totals.Samples} contact samples, model contacts {contactsFrom}:");
            TestContext.Out.WriteLine($"  skating (leg lengths/s, sample-weighted): truth {truthMean:F3}, off {offMean:F3}, locked {lockedMean:F3}, labelled {labelledMean:F3}, truth's contacts {knownMean:F3}");
            TestContext.Out.WriteLine($"  locked ÷ off {lockedMean / offMean:F2} (goal ≤ {(modelFrames == 15 ? 0.30 : 0.40):F2}); locked ÷ truth {lockedMean / truthMean:F1} (goal ≤ {(modelFrames == 15 ? 3.0 : 6.0):F1})");
            TestContext.Out.WriteLine($"  labelled ÷ off {labelledMean / offMean:F2}, ÷ truth {labelledMean / truthMean:F1}; truth's contacts ÷ off {knownMean / offMean:F2}, ÷ truth {knownMean / truthMean:F1}");
            TestContext.Out.WriteLine($"  position error locked ÷ off {error:F3} (non-key-frame-weighted; goal ≤ 1.02)");
            TestContext.Out.WriteLine($"  planted samples held within 1 % of a leg of their height: {100.0 * totals.HeldWithin / totals.Held:F1} % of {totals.Held} (largest {totals.WorstHeight:F4} leg lengths)");
            TestContext.Out.WriteLine($"  foot joints' acceleration over all frames locked ÷ off {totals.LockedAcceleration / totals.OffAcceleration:F3}, the truth's ÷ off {totals.TruthAcceleration / totals.OffAcceleration:F3} (smoothness: a hold that pops shows here, not in skating)");
            TestContext.Out.WriteLine($"  the truth's contacts added to the locker's labels ÷ off {totals.TruthAdded / totals.Samples / offMean:F2}, ÷ truth {totals.TruthAdded / totals.Samples / truthMean:F1}");
            if (classifier != null)
            {
                TestContext.Out.WriteLine($"  experimental classifier (threshold {classifier.Threshold}) on the filled rig frames: precision {(double)totals.ClassifierHits / Math.Max(totals.ClassifierSaid, 1):F3}, recall {(double)totals.ClassifierHits / Math.Max(totals.ClassifierActual, 1):F3} (all four joints)");
                TestContext.Out.WriteLine($"  locked with its contacts ÷ off {totals.Classified / totals.Samples / offMean:F2}; its contacts added to the labels ÷ off {totals.ClassifierAdded / totals.Samples / offMean:F2}");
            }

            Assert.That(totals.Samples, Is.GreaterThan(1000), "contact samples");
            Assert.That(lockedMean, Is.LessThan(offMean), "locked skates less than off");
            Assert.That(knownMean, Is.LessThan(offMean), "locked with the truth's contacts skates less than off");
        }

        /// <summary>
        /// Issue 29's experimental contact classifier over the filled motion, if one was exported
        /// ($DELTAINTERP_CONTACT_CLASSIFIER, else Training/runs/features/classifier.json): its column is measured beside the
        /// others; without it the column is left out. Its golden vectors (one validation bake) are checked first.
        /// </summary>
        private static FilledMotionContactClassifier? Classifier()
        {
            string? path = Environment.GetEnvironmentVariable("DELTAINTERP_CONTACT_CLASSIFIER");
            if (string.IsNullOrEmpty(path) && TestEnvironment.RepositoryRoot != null) path = Path.Combine(TestEnvironment.RepositoryRoot, "Training", "runs", "features", "classifier.json");
            if (string.IsNullOrEmpty(path) || !File.Exists(path)) return null;
            JsonValue doc = JsonValue.Parse(File.ReadAllText(path), path);
            var classifier = new FilledMotionContactClassifier(doc);
            JsonValue golden = doc.ExpectMember("golden");
            double[] feet = golden.ExpectMember("feet").ExpectNumbers("feet", -1);
            int[] keys = Array.ConvertAll(golden.ExpectMember("keys").ExpectNumbers("keys", -1), k => (int)k);
            double[] expected = golden.ExpectMember("probabilities").ExpectNumbers("probabilities", feet.Length / 3);
            float[] got = classifier.Probabilities(feet, keys, golden.ExpectMember("leg_length").ExpectNumber("leg_length"), golden.ExpectMember("frame_time").ExpectNumber("frame_time"));
            double worst = 0;
            for (int i = 0; i < got.Length; i++)
            {
                if (expected[i] < 0) Assert.That(float.IsNaN(got[i]), Is.True, $"{path}: golden value {i} is a key's");
                else worst = Math.Max(worst, Math.Abs(got[i] - expected[i]));
            }

            TestContext.Out.WriteLine($"classifier {path}: golden probabilities reproduced within {worst:G3}");
            Assert.That(worst, Is.LessThan(1e-4), "the C# classifier is Python's");
            return classifier;
        }

        /// <summary>
        /// <paramref name="clip"/> locked with the contacts the locker labels by itself plus those <paramref name="added"/>
        /// (frame, channel) says are planted: the union as given contacts (<see cref="FootLocker"/>'s runs of flags).
        /// </summary>
        private static MotionClip LockedWithLabelsAnd(MotionClip clip, int[] keys, FootRig feet, Func<int, int, bool> added)
        {
            var labeller = new FootLocker(feet, new FootLockSettings());
            labeller.Plan(clip, keys);
            var union = new bool[clip.FrameCount * FootLocker.ChannelCount];
            for (int f = 0; f < clip.FrameCount; f++)
            {
                for (int c = 0; c < FootLocker.ChannelCount; c++) union[f * FootLocker.ChannelCount + c] = labeller.IsPlanted(f, c) || added(f, c);
            }

            MotionClip locked = Copy(clip);
            new FootLocker(feet, new FootLockSettings()).LockWithContacts(locked, keys, union);
            return locked;
        }

        /// <summary>The classifier's contacts for the model-rate bake of <paramref name="off"/>, on the rig clip's frames (its first at <paramref name="rigStart"/> seconds).</summary>
        private static FootContacts Classify(FilledMotionContactClassifier classifier, BakeRun off, MotionClip rigClip, double rigStart)
        {
            MotionClip baked = off.Methods[0].OnModel;
            var modelKeys = new int[off.ModelKeys.Count];
            for (int i = 0; i < modelKeys.Length; i++) modelKeys[i] = off.ModelKeys[i] - off.ModelKeys[0];
            FootRig modelFeet = FootRig.ForModel(baked.Skeleton);
            float[] p = classifier.Probabilities(FootSkating.FootPositions(baked, 0, baked.FrameCount, modelFeet.FootJoints), modelKeys, modelFeet.LegLength, baked.FrameTime);
            var predicted = new FootContacts();
            predicted.Clear(baked.FrameCount);
            for (int f = 0; f < baked.FrameCount; f++)
            {
                if (!float.IsNaN(p[f * 4])) predicted.SetPredicted(f, 1, p.AsSpan(f * 4, 4), classifier.Threshold);
            }

            var onRig = new FootContacts();
            predicted.ResampleInto(onRig, rigClip.FrameCount, rigClip.FrameTime, baked.FrameTime, rigStart - off.ModelKeys[0] * baked.FrameTime);
            return onRig;
        }

        /// <summary>Every planted sample's height against the height the locker holds it at.</summary>
        private static void HeightHold(FootLocker locker, MotionClip locked, FootRig feet, int[] keys, Totals totals)
        {
            double[] positions = FootSkating.FootPositions(locked, 0, locked.FrameCount, feet.FootJoints);
            int n = feet.FootJoints.Count;
            var isKey = new bool[locked.FrameCount];
            foreach (int k in keys) isKey[k] = true;
            for (int f = 0; f < locked.FrameCount; f++)
            {
                if (isKey[f]) continue;
                for (int c = 0, i = 0; c < FootLocker.ChannelCount; c++)
                {
                    if (c % 2 == 1 && !feet[c / 2].HasToe) continue;
                    int joint = i++;
                    if (!locker.IsPlanted(f, c) || locker.LockWeight(f, c) < 1) continue;
                    double off = Math.Abs(positions[(f * n + joint) * 3 + 1] - locker.HeldAt(f, c).Y) / feet.LegLength;
                    totals.Held++;
                    if (off <= 0.01) totals.HeldWithin++;
                    totals.WorstHeight = Math.Max(totals.WorstHeight, off);
                }
            }
        }

        /// <summary>
        /// The summed magnitude of every foot joint's acceleration (second difference ÷ dt², leg lengths per second²) over
        /// the clip's inner frames: locking that eases a foot in and out leaves it near the unlocked motion's, one that snaps
        /// a foot onto its spot or lets it go at once raises it however little the foot skates on its planted frames.
        /// </summary>
        private static double Acceleration(MotionClip clip, FootRig feet)
        {
            int n = feet.FootJoints.Count, frames = clip.FrameCount;
            double[] p = FootSkating.FootPositions(clip, 0, frames, feet.FootJoints);
            double dt2 = clip.FrameTime * clip.FrameTime, sum = 0;
            for (int f = 1; f + 1 < frames; f++)
            {
                for (int j = 0; j < n; j++)
                {
                    double a2 = 0;
                    for (int k = 0; k < 3; k++)
                    {
                        double a = p[((f + 1) * n + j) * 3 + k] - 2 * p[(f * n + j) * 3 + k] + p[((f - 1) * n + j) * 3 + k];
                        a2 += a * a;
                    }

                    sum += Math.Sqrt(a2) / dt2 / feet.LegLength;
                }
            }

            return sum;
        }

        /// <summary>The truth's flags per foot joint (frames × the rig's foot joints) as the locker's channels (frames × 4; a missing toe never planted).</summary>
        private static bool[] Channels(bool[] planted, FootRig feet, int frames)
        {
            int n = feet.FootJoints.Count;
            var channels = new bool[frames * FootLocker.ChannelCount];
            for (int c = 0, i = 0; c < FootLocker.ChannelCount; c++)
            {
                bool present = c % 2 == 0 || feet[c / 2].HasToe;
                if (!present) continue;
                for (int f = 0; f < frames; f++) channels[f * FootLocker.ChannelCount + c] = planted[f * n + i];
                i++;
            }

            return channels;
        }

        private static void AssertKeysUnchanged(MotionClip off, MotionClip locked, int[] keys, string name)
        {
            int j = off.Skeleton.JointCount;
            foreach (int key in keys)
            {
                int f = key - keys[0];
                for (int i = 0; i < 4 * j; i++) Assert.That(locked.LocalRotations[f * 4 * j + i], Is.EqualTo(off.LocalRotations[f * 4 * j + i]), $"{name}: key {key}");
            }
        }

        private static double Max(double[] a, double[] b)
        {
            double most = 0;
            for (int i = 0; i < a.Length; i++) most = Math.Max(most, Math.Abs(a[i] - b[i]));
            return most;
        }

        /// <summary>Frames <paramref name="first"/>.. of <paramref name="clip"/>, <paramref name="count"/> of them.</summary>
        private static MotionClip Frames(MotionClip clip, int first, int count)
        {
            int p = 3 * clip.Skeleton.JointCount, r = 4 * clip.Skeleton.JointCount;
            return new MotionClip(clip.Skeleton, count, clip.FrameTime, clip.LocalPositions.AsSpan(first * p, count * p).ToArray(), clip.LocalRotations.AsSpan(first * r, count * r).ToArray());
        }

        private static MotionClip Copy(MotionClip clip) =>
            new MotionClip(clip.Skeleton, clip.FrameCount, clip.FrameTime, (double[])clip.LocalPositions.Clone(), (double[])clip.LocalRotations.Clone());

        private sealed class Totals
        {
            public double Truth, Off, Locked, Labelled, Known, OffError, LockedError, WorstHeight;
            public double LastOff, LastLocked, LastLabelled, LastKnown;
            public double TruthAdded, Classified, ClassifierAdded;
            public double OffAcceleration, LockedAcceleration, TruthAcceleration;
            public int ClassifierHits, ClassifierSaid, ClassifierActual;
            public int Samples, Held, HeldWithin;

            public void Add(FootSkating truth, FootSkating off, FootSkating locked, FootSkating labelled, FootSkating known, double offError, double lockedError, int frames)
            {
                int s = truth.ContactSamples;
                if (s == 0) return;
                Samples += s;
                Truth += s * truth.MeanSpeed;
                Off += s * (LastOff = off.MeanSpeed);
                Locked += s * (LastLocked = locked.MeanSpeed);
                Labelled += s * (LastLabelled = labelled.MeanSpeed);
                Known += s * (LastKnown = known.MeanSpeed);
                OffError += frames * offError;
                LockedError += frames * lockedError;
            }
        }
    }
}
