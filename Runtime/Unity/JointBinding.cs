using System;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>Which bone of the character drives a model joint, when their names differ.</summary>
    [Serializable]
    public struct JointBinding
    {
        /// <summary>The model joint's name (as in the model's skeleton, e.g. <c>LeftUpLeg</c>).</summary>
        [Tooltip("The model joint's name, e.g. LeftUpLeg.")]
        public string joint;

        /// <summary>The name of the character's bone (a Transform under the Animator) that plays it.</summary>
        [Tooltip("The name of the character's bone (a Transform under the Animator) that plays this joint.")]
        public string bone;
    }
}
