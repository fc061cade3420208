using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// What a <see cref="MotionInbetweener"/> was built from (model, engine, rig, joint map, reference pose,
    /// past frames, neural Animator transitions): an edit to any of these re-initialises the component, while an edit of the blend times
    /// or the default length applies without one (they are read at each request and frame).
    /// </summary>
    internal sealed class SettingsSnapshot
    {
        private InbetweeningModel? _model;
        private string _backend = "";
        private CharacterRigKind _rig;
        private BuiltInJointMap _jointMap;
        private TextAsset? _jointMapJson;
        private JointBinding[] _joints = new JointBinding[0];
        private ReferencePoseSource _referencePose;
        private AnimationClip? _referenceClip;
        private float _referenceClipTime;
        private int _pastFrames;
        private string _neuralTransitions = "";
        private AvatarMask?[] _masks = new AvatarMask?[0];

        public static SettingsSnapshot Take(InbetweenerSettings s) => new SettingsSnapshot
        {
            _model = s.Model,
            _backend = s.Backend,
            _rig = s.Rig,
            _jointMap = s.JointMap,
            _jointMapJson = s.JointMapJson,
            _joints = s.Joints != null ? (JointBinding[])s.Joints.Clone() : new JointBinding[0],
            _referencePose = s.ReferencePose,
            _referenceClip = s.ReferenceClip,
            _referenceClipTime = s.ReferenceClipTime,
            _pastFrames = s.PastFrames,
            _neuralTransitions = Describe(s.NeuralTransitions),
            _masks = Masks(s.NeuralTransitions),
        };

        /// <summary>True when <paramref name="s"/> still builds the same component.</summary>
        public bool Matches(InbetweenerSettings s)
        {
            if (_model != s.Model || _backend != s.Backend || _rig != s.Rig || _jointMap != s.JointMap || _jointMapJson != s.JointMapJson) return false;
            if (_referencePose != s.ReferencePose || _referenceClip != s.ReferenceClip || _referenceClipTime != s.ReferenceClipTime || _pastFrames != s.PastFrames) return false;
            // Neural transitions are built into the watcher and the job's bone mask: an edit rebuilds them.
            if (_neuralTransitions != Describe(s.NeuralTransitions)) return false;
            AvatarMask?[] masks = Masks(s.NeuralTransitions);
            if (masks.Length != _masks.Length) return false;
            for (int i = 0; i < masks.Length; i++)
            {
                if (masks[i] != _masks[i]) return false;
            }

            JointBinding[] joints = s.Joints ?? new JointBinding[0];
            if (joints.Length != _joints.Length) return false;
            for (int i = 0; i < joints.Length; i++)
            {
                if (joints[i].joint != _joints[i].joint || joints[i].bone != _joints[i].bone) return false;
            }

            return true;
        }

        // The entries' values as text (the entries are edited in place by the inspector, so a reference compare would miss an edit).
        private static string Describe(NeuralTransitionLayer[] layers)
        {
            var text = new System.Text.StringBuilder();
            foreach (NeuralTransitionLayer l in layers)
            {
                if (l == null) continue;
                text.Append(l.layer).Append('|').Append(l.enabled).Append('|').Append(l.minSeconds).Append('|').Append(l.maxSeconds).Append('|');
                text.Append(string.Join(",", l.includeTags ?? new string[0])).Append('|').Append(string.Join(",", l.excludeTags ?? new string[0])).Append(';');
            }

            return text.ToString();
        }

        private static AvatarMask?[] Masks(NeuralTransitionLayer[] layers)
        {
            var masks = new AvatarMask?[layers.Length];
            for (int i = 0; i < layers.Length; i++) masks[i] = layers[i]?.maskedLayerAbove;
            return masks;
        }
    }
}
